// Subcommand registry of the rtamp CLI. Each cmd_<name>.cpp defines one
// subcommand and registers it with a static Registrar:
//
//   static rtamp::cli::Registrar reg{"ltl2ba", "Translate LTL to a Büchi automaton",
//       [](CLI::App& sub) { /* add options */ return [&]() -> int { /* run */ return 0; }; }};
//
// The setup function adds options to `sub` and returns the action to run when
// the subcommand is chosen; the action returns the exit code. Errors a user
// can cause are thrown as rtamp::Error and turned by main() into one line on
// stderr and exit code 2 (report_error: the one way rtamp prints an error).
// Typed options (numbers, seeds, names from the planner's registry): options.hpp.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

#include "rtamp/util/error.hpp"

namespace rtamp::cli {

using Action = std::function<int()>;
using Setup = std::function<Action(CLI::App&)>;

struct Command {
  std::string name;
  std::string description;
  Setup setup;
};

std::vector<Command>& commands();

// "rtamp: error: MESSAGE" on stderr, control bytes escaped, then the detail's
// lines (e.g. the input with a caret).
void report_error(const std::string& message, const std::string& detail = {});
void report_error(const rtamp::Error& e);

struct Registrar {
  Registrar(std::string name, std::string description, Setup setup) {
    commands().push_back({std::move(name), std::move(description), std::move(setup)});
  }
};

}  // namespace rtamp::cli
