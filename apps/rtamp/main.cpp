// rtamp — command-line front end. Subcommands register themselves (command.hpp).
#include <algorithm>
#include <iostream>
#include <memory>

#include "command.hpp"
#include "rtamp/robot/ompl_logging.hpp"
#include "rtamp/sim/mujoco_logging.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::cli {
std::vector<Command>& commands() {
  static std::vector<Command> all;
  return all;
}
}  // namespace rtamp::cli

int main(int argc, char** argv) {
  using namespace rtamp::cli;
  // The library changes no process-wide state on its own; the CLI keeps MuJoCo's
  // warnings in mjData's counters only and OMPL to errors (docs/library.md).
  rtamp::sim::install_mujoco_log_handler();
  rtamp::robot::quiet_ompl_logging();
  CLI::App app{
      "rtamp — reactive task and motion planning under linear temporal logic.\n"
      "Run 'rtamp COMMAND --help' for the options of a command."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("rtamp 0.1.0"));
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  std::vector<std::pair<CLI::App*, Action>> actions;
  for (auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    actions.emplace_back(sub, c.setup(*sub));
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = app.exit(e);
    return code == 0 ? 0 : 2;
  }
  try {
    for (auto& [sub, action] : actions)
      if (sub->parsed()) return action();
  } catch (const rtamp::Error& e) {
    std::cerr << "rtamp: error: " << e.what() << "\n";
    if (!e.detail().empty()) std::cerr << e.detail() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rtamp: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
