// Typed options of the rtamp CLI, shared by every subcommand: numbers with a
// documented range, seeds, and names chosen from a list (the planner's
// registry, plan/registry.hpp, for algorithms and cost models). Each adder
// registers a CLI11 option whose help text states the accepted range or names
// and whose value is checked while the command line is parsed, before any
// command runs; a bad value is a CLI::ValidationError "--opt: WHAT" that
// main() prints as one line `rtamp: error: --opt: WHAT`, exit 2.
//
// Parsing rules (parse_real / parse_integer / parse_seed, also used alone):
//  - the whole text must be the number: no blanks, no trailing garbage;
//  - reals are decimal or scientific; "inf" (also "infinity", any case) only
//    where the range allows no limit; "nan" never;
//  - integers are decimal digits with an optional sign, within [min, max];
//  - seeds are unsigned 64-bit: 0 .. 18446744073709551615, no sign.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "rtamp/util/names_table.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::cli {

struct RealRange {
  double min = 0;
  double max = std::numeric_limits<double>::max();
  bool min_open = false;   // (min, ...] instead of [min, ...]
  bool allow_inf = false;  // "inf": no limit
  const char* inf_means = "no limit";  // what "inf" stands for, in the text
  std::string text() const;  // "> 0 or inf (no limit)", "in [0, 1]"
};

// Throws rtamp::Error "WHAT" (without the option name).
double parse_real(std::string_view text, const RealRange& range);
long long parse_integer(std::string_view text, long long min, long long max);
std::string integer_range(long long min, long long max);  // "in [1, 64]", ">= 1" (max = LLONG_MAX)
std::uint64_t parse_seed(std::string_view text);

CLI::Option* add_real(CLI::App& app, const std::string& name, double& target, const RealRange& range,
                      const std::string& description);
CLI::Option* add_integer_with(CLI::App& app, const std::string& name, std::function<void(long long)> store,
                              long long min, long long max, const std::string& default_text,
                              const std::string& description);
template <typename Int>
CLI::Option* add_integer(CLI::App& app, const std::string& name, Int& target, long long min, long long max,
                         const std::string& description) {
  return add_integer_with(
      app, name, [&target](long long v) { target = static_cast<Int>(v); }, min, max, std::to_string(target),
      description);
}
CLI::Option* add_seed(CLI::App& app, const std::string& name, std::uint64_t& target, const std::string& description);

struct Choice {
  std::string name, description;  // description may be empty
};
// The algorithms / cost models of the registry, in its order.
std::vector<Choice> algorithm_choices();
// The names of a library table (util/names_table.hpp), in its order.
template <class E>
std::vector<Choice> choices_of(const NameTable<E>& table) {
  std::vector<Choice> out;
  for (const auto& n : table) out.push_back({n.name, n.description});
  return out;
}
std::vector<Choice> cost_model_choices();
// A name from `choices` (an unknown one: "unknown VALUE 'x' (did you mean 'y'?)").
// The help text lists the names, with their descriptions when there are any.
CLI::Option* add_choice(CLI::App& app, const std::string& name, std::string& target, const std::vector<Choice>& choices,
                        const std::string& description);
// The same, handing the checked name to `store` (e.g. to set an enum); `default_name` is shown in --help.
CLI::Option* add_choice_with(CLI::App& app, const std::string& name, const std::vector<Choice>& choices,
                             const std::string& default_name, std::function<void(const std::string&)> store,
                             const std::string& description);
// Repeatable: every occurrence must be a name from `choices`.
CLI::Option* add_choices(CLI::App& app, const std::string& name, std::vector<std::string>& target,
                         const std::vector<Choice>& choices, const std::string& description);

// The MCAP profiles (episode/mcap_profile.hpp), for --mcap-profile.
std::vector<Choice> mcap_profile_choices();
// The MCAP compressions (mcap_writer.hpp), for --mcap-compression / --compression.
std::vector<Choice> mcap_compression_choices();

// The positional SCENARIO: a YAML file or a built-in name (the help lists them all).
CLI::Option* add_scenario(CLI::App& app, std::string& target);

// `TIME@LTL` (--new-task): a new task at world time TIME (finite, >= 0) by
// "command line", its task located as "--new-task #N:1:COL" (N: `occurrence`,
// 1-based, as --change counts). Throws rtamp::Error
// (without the option name). The formula is checked later, with the scenario
// (exec::check_task_schedule).
world::TaskChange parse_new_task(std::string_view text, int occurrence = 1);
// Repeatable --new-task TIME@LTL into `target`.
CLI::Option* add_new_task(CLI::App& app, std::vector<world::TaskChange>& target);

// Output files: throws rtamp::OutputError "OPTION: cannot write 'PATH': WHY"
// unless `path` can be written as util/output_file.hpp writes it (a new file in
// a writable directory, a writable regular file no other process is writing,
// a FIFO or a character device). Nothing is created or changed.
void check_output_file(const std::string& option, const std::string& path);

// Output directories: throws rtamp::Error "OPTION: cannot write into 'DIR': WHY"
// unless `dir` is a writable directory or can be created (its nearest existing
// ancestor is a writable directory). Nothing is created.
void check_output_dir(const std::string& option, const std::string& dir);

}  // namespace rtamp::cli
