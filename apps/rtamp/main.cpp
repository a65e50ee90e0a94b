// rtamp — command-line front end. Subcommands register themselves (command.hpp);
// main() speaks for all of them: every error, the argument parser's included,
// is one line `rtamp: error: WHERE: WHAT` on stderr (control bytes escaped,
// util/format.hpp), exit code 2 for bad input, 3 for an internal error.
#include <algorithm>
#include <cctype>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <memory>
#include <sstream>
#include <vector>

#include "command.hpp"
#include "rtamp/robot/ompl_logging.hpp"
#include "rtamp/sim/mujoco_logging.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/util/version.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::cli {
std::vector<Command>& commands() {
  static std::vector<Command> all;
  return all;
}

void report_error(const std::string& message, const std::string& detail) {
  std::cerr << "rtamp: error: " << rtamp::escape_text(message) << "\n";
  if (!detail.empty()) {
    // Keep the detail's own lines (input line, caret), escape inside them.
    std::size_t from = 0;
    while (from <= detail.size()) {
      const std::size_t nl = std::min(detail.find('\n', from), detail.size());
      std::cerr << rtamp::escape_text(std::string_view(detail).substr(from, nl - from)) << "\n";
      from = nl + 1;
    }
  }
}

void report_error(const rtamp::Error& e) { report_error(e.what(), e.detail()); }

}  // namespace rtamp::cli

namespace {

// CLI11's own wording, in the form of the rest of rtamp's messages.
std::string parser_message(const CLI::ParseError& e) {
  std::string m = e.what();
  const char* one = "The following argument was not expected: ";
  if (m.rfind(one, 0) == 0) {
    const std::string rest = m.substr(std::strlen(one));
    const bool option = !rest.empty() && rest[0] == '-';
    return std::string(option ? "unknown option " : "unexpected argument ") + rtamp::world::quoted(rest);
  }
  // Several, listed by CLI11 last first ("1e3 --seed" for `--seed 1e3`): the
  // first unknown option of the command line, else the first argument.
  const char* several = "The following arguments were not expected: ";
  if (m.rfind(several, 0) == 0) {
    std::vector<std::string> words;
    std::istringstream in(m.substr(std::strlen(several)));
    for (std::string w; in >> w;) words.insert(words.begin(), w);
    for (const std::string& w : words)
      if (w.size() > 1 && w[0] == '-' && !std::isdigit(static_cast<unsigned char>(w[1])) && w[1] != '.')
        return "unknown option " + rtamp::world::quoted(w);
    if (!words.empty())
      return "unexpected argument " + rtamp::world::quoted(words.front()) +
             (words.size() > 1 ? " (and " + std::to_string(words.size() - 1) + " more)" : "");
  }
  // "--seed: 1 required SEED missing"
  const auto colon = m.find(": 1 required ");
  if (colon != std::string::npos && m.size() > 8 && m.compare(m.size() - 8, 8, " missing") == 0)
    return m.substr(0, colon) + ": needs a value";
  if (!m.empty() && m[0] >= 'A' && m[0] <= 'Z' && !(m.size() > 1 && m[1] >= 'A' && m[1] <= 'Z'))
    m[0] = static_cast<char>(m[0] - 'A' + 'a');
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rtamp::cli;
  // The library changes no process-wide state on its own; the CLI keeps MuJoCo's
  // warnings in mjData's counters only and OMPL to errors (docs/library.md).
  rtamp::sim::install_mujoco_log_handler();
  rtamp::robot::quiet_ompl_logging();
  // A reader that goes away (a pipe to `head`, an ffmpeg that failed) is a write
  // error the code reports, never a signal.
  std::signal(SIGPIPE, SIG_IGN);
  // A file-size limit (ulimit -f) is a write error that names the file (util/output_file.hpp), not a signal.
  std::signal(SIGXFSZ, SIG_IGN);
  // Mesa's llvmpipe (the CPU renderer of the cameras and pictures here) renders on the
  // calling thread unless the user's LP_NUM_THREADS says otherwise: a camera episode
  // costs less so, alone or in a batch (docs/benchmarks.md "Camera frames at 10x").
  setenv("LP_NUM_THREADS", "0", 0);
  rtamp::robot::register_ik_cost_model();  // before the subcommands list the cost models
  CLI::App app{
      "rtamp — reactive task and motion planning under linear temporal logic.\n"
      "Run 'rtamp COMMAND --help' for the options of a command."};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("rtamp ") + rtamp::version());
  auto& cmds = commands();
  std::sort(cmds.begin(), cmds.end(), [](const Command& a, const Command& b) { return a.name < b.name; });
  std::vector<std::string> names;
  for (const auto& c : cmds) names.push_back(c.name);
  std::vector<std::pair<CLI::App*, Action>> actions;
  for (auto& c : cmds) {
    CLI::App* sub = app.add_subcommand(c.name, c.description);
    actions.emplace_back(sub, c.setup(*sub));
  }
  // The command: the first argument, unless it is an option of rtamp itself.
  std::string command;
  if (argc > 1 && argv[1][0] != '-') {
    command = argv[1];
    if (std::find(names.begin(), names.end(), command) == names.end()) {
      report_error("unknown command " + rtamp::world::quoted(command) + rtamp::world::suggestion(command, names) +
                  "; run 'rtamp --help'");
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    if (command.empty() && dynamic_cast<const CLI::RequiredError*>(&e)) {
      std::string list;
      for (const auto& n : names) list += (list.empty() ? "" : ", ") + n;
      report_error("no command given (one of: " + list + "); run 'rtamp --help'");
    } else {
      report_error(parser_message(e) + (command.empty() ? "; run 'rtamp --help'" : "; run 'rtamp " + command + " --help'"));
    }
    return 2;
  } catch (const rtamp::Error& e) {
    report_error(e);
    return 2;
  }
  try {
    for (auto& [sub, action] : actions)
      if (sub->parsed()) return action();
  } catch (const rtamp::Error& e) {
    report_error(e);
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rtamp: internal error: " << rtamp::escape_text(e.what()) << "\n";
    return 3;
  }
  return 0;
}
