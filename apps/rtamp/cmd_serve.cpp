// rtamp serve — a running episode (or a finished one's log, --replay) served to a web
// page on 127.0.0.1 (serve/, docs/serve.md): watch the arm, the behavior tree, the plan
// and the automaton, and be the person in the loop. The first line on stdout is the
// URL. SIGINT / SIGTERM end the episode cleanly (the log gets its end record) and stop
// the server, exit code 130 / 143 if the episode was still running.
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <thread>

#include "command.hpp"
#include "episode_args.hpp"
#include "options.hpp"
#include "rtamp/serve/live_episode.hpp"
#include "rtamp/serve/replay.hpp"
#include "rtamp/serve/server.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/util/text_file.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void on_serve_signal(int sig) { g_signal.store(sig); }

// <dir of the executable>/../share/rtamp/web
std::string default_web_root() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec) return "";
  return (exe.parent_path().parent_path() / "share" / "rtamp" / "web").string();
}

void check_input_file(const std::string& option, const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_regular_file(path, ec)) return;
  const bool exists = std::filesystem::exists(path, ec);
  throw rtamp::Error(option + ": cannot read '" + path + "': " +
                     (!exists ? "no such file" : std::filesystem::is_directory(path, ec) ? "it is a directory"
                                                                                         : "it is not a regular file"));
}

rtamp::cli::Registrar reg{
    "serve",
    "Serve a running episode (or an episode log, --replay) to a web page: watch it and intervene as the person in the loop",
    [](CLI::App& app) -> rtamp::cli::Action {
      struct Opts : rtamp::cli::EpisodeArgs {
        std::string host = "127.0.0.1", replay, web_root;
        std::vector<std::string> allow_origins;
        double speed = 1;
        int port = 8080;
        bool quiet = false, paused = false, exit_at_end = false;
      };
      auto o = std::make_shared<Opts>();
      app.description(
          "Run one episode of rtamp's reactive loop on SCENARIO (as `rtamp run` does) paced to wall time, and\n"
          "serve it to a web page: the 3-D scene with the arm, the behavior tree with live statuses, the plan,\n"
          "the task's automaton and a timeline. On the page you are the person in the loop: move, add or\n"
          "remove blocks and trays, take the held thing out of the gripper; each becomes an intervention of the\n"
          "episode, checked like a scripted one, and appears in the log. --replay LOG serves a finished\n"
          "episode's JSON Lines log instead (scrub with seek). Listens on 127.0.0.1 only unless --host says\n"
          "otherwise; prints the URL as the first line. docs/serve.md.");
      rtamp::cli::add_episode_options(app, *o, "Write the episode as JSON Lines to FILE (with `frame` records for replays)");
      app.add_option("--host", o->host, "Address to listen on (default 127.0.0.1: this machine only)");
      rtamp::cli::add_integer(app, "--port", o->port, 0, 65535, "Port to listen on (0: any free port)");
      rtamp::cli::add_real(app, "--speed", o->speed, {0, 1000},
                           "World seconds per wall second (0: as fast as possible)");
      app.add_flag("--paused", o->paused, "Start paused (the first plan is made; resume or step on the page)");
      app.add_option("--replay", o->replay, "Serve this episode log (JSON Lines, from run or serve --log) instead of running");
      app.add_option("--allow-origin", o->allow_origins,
                     "Let pages of this origin (http[s]://HOST[:PORT]) use the WebSocket, e.g. a page that embeds this "
                     "one; repeatable (default: only the served page's own origin)")
          ->allow_extra_args(false);
      app.add_option("--web-root", o->web_root, "The page's files (default: <exe dir>/../share/rtamp/web)");
      app.add_flag("--exit-at-end", o->exit_at_end, "Stop serving when the episode (or replay) ends");
      app.add_flag("--quiet", o->quiet, "No timeline");
      return [o]() -> int {
        using namespace rtamp;
        serve::ServerOptions so;
        for (const std::string& text : o->allow_origins) {
          std::string why;
          const auto origin = serve::parse_origin(text, &why);
          if (!origin) throw Error("--allow-origin: " + why);
          so.allowed_origins.push_back(*origin);
        }
        const world::Scenario scenario = world::load_scenario(o->scenario);
        task::validate_task(scenario);
        const episode::EpisodeOptions episode_options = rtamp::cli::episode_options(*o);
        {  // no output is an input or another output (by device and inode)
          FileSet files;
          if (path_exists(o->scenario)) files.input("SCENARIO", o->scenario);
          if (!o->replay.empty()) files.input("--replay", o->replay);
          if (!episode_options.outputs.log.empty()) files.output("--log", episode_options.outputs.log);
          if (!episode_options.outputs.mcap.empty()) files.output("--mcap", episode_options.outputs.mcap);
        }
        if (!episode_options.outputs.log.empty()) rtamp::cli::check_output_file("--log", episode_options.outputs.log);
        if (!episode_options.outputs.mcap.empty()) rtamp::cli::check_output_file("--mcap", episode_options.outputs.mcap);
        if (!episode_options.outputs.trees.empty())
          rtamp::cli::check_output_dir("--trees", episode_options.outputs.trees);
        if (!o->replay.empty()) check_input_file("--replay", o->replay);
        so.host = o->host;
        so.port = static_cast<unsigned short>(o->port);
        so.web_root = o->web_root.empty() ? default_web_root() : o->web_root;
        if (!o->web_root.empty() && !std::filesystem::is_directory(o->web_root))
          throw Error("--web-root: '" + o->web_root + "' is not a directory");

        serve::Server server(so);  // binds first: a bad address or a busy port is refused before anything runs
        std::unique_ptr<serve::LiveEpisode> live;
        std::unique_ptr<serve::Replay> replay;
        serve::RequestHandler* handler = nullptr;
        if (!o->replay.empty()) {
          if (!episode_options.loop.task_changes.empty())
            throw Error("--new-task: a replay shows the tasks of a finished episode as they were given; new tasks "
                        "are for live episodes");
          serve::ReplayOptions ro;
          ro.speed = o->speed;
          ro.paused = o->paused;
          replay = std::make_unique<serve::Replay>(scenario, o->replay, ro);
          if (!episode_options.outputs.log.empty() || !episode_options.outputs.trees.empty() ||
              !episode_options.outputs.mcap.empty())
            throw Error("--replay: serves a finished episode's log; --log, --mcap and --trees are for live episodes "
                        "(rtamp log to-mcap converts a log)");
          handler = replay.get();
        } else {
          serve::LiveOptions lo;
          lo.episode = episode_options;
          episode::EpisodeOptions& opt = lo.episode;
          if (!o->quiet)
            opt.outputs.timeline = [](const std::string& line) {
              std::fputs(line.c_str(), stdout);
              std::fputc('\n', stdout);
              std::fflush(stdout);
            };
          opt.loop.interrupt = &g_signal;
          lo.speed = o->speed;
          lo.paused = o->paused;
          live = std::make_unique<serve::LiveEpisode>(scenario, lo);
          handler = live.get();
        }
        std::printf("rtamp serve: http://%s:%u/\n", o->host.find(':') != std::string::npos ? ("[" + o->host + "]").c_str()
                                                                                          : o->host.c_str(),
                    static_cast<unsigned>(server.port()));
        std::fflush(stdout);
        if (!server.has_page())
          std::fprintf(stderr,
                       "rtamp serve: no page in '%s' (index.html missing): build the web bundle or pass --web-root; "
                       "the API (/api/hello) and the WebSocket (/ws) work\n",
                       so.web_root.c_str());
        std::signal(SIGINT, on_serve_signal);
        std::signal(SIGTERM, on_serve_signal);
        server.start(*handler);
        int code = 0;
        if (live) {
          live->start();
          while (!live->ended() && g_signal.load() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(20));
          if (g_signal.load() != 0) live->stop();
          exec::EpisodeMetrics m;
          try {
            m = live->wait();
          } catch (...) {  // a lost --log or --mcap: the server stops before the episode goes, then exit 2
            server.stop();
            std::signal(SIGINT, SIG_DFL);
            std::signal(SIGTERM, SIG_DFL);
            throw;
          }
          if (!o->quiet) {
            const std::string completion = m.completion_time ? format_number(*m.completion_time) + " s" : "none";
            std::printf("\n%s: %s\n  completion %s (world time), %d replans, %d interventions (%d applied, %d refused)\n",
                        m.success ? "SUCCESS" : "FAILURE", escape_text(m.reason).c_str(), completion.c_str(),
                        m.replans, m.interventions, m.interventions_applied, m.interventions_refused);
            std::fflush(stdout);
          }
          code = m.end == exec::EndReason::Interrupted ? (g_signal.load() == SIGTERM ? 143 : 130) : (m.success ? 0 : 1);
          const serve::InterventionStats st = live->stats();
          if (!st.latency_ms.empty()) {
            std::vector<double> v = st.latency_ms;
            std::sort(v.begin(), v.end());
            std::fprintf(stderr, "rtamp serve: %zu interventions from pages; receipt to applied: median %.3f ms, max %.3f ms\n",
                         v.size(), v[v.size() / 2], v.back());
          }
        } else {
          replay->start();
          while (!(o->exit_at_end && replay->ended()) && g_signal.load() == 0)
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
          replay->stop();
        }
        if (live && !o->exit_at_end)
          while (g_signal.load() == 0) std::this_thread::sleep_for(std::chrono::milliseconds(50));
        // --exit-at-end: the pages get the end (messages still queued when it came) before the server goes.
        if (g_signal.load() == 0) server.drain(std::chrono::seconds(2));
        server.stop();
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        if (!live) return g_signal.load() == SIGTERM ? 143 : g_signal.load() ? 130 : 0;
        return code;
      };
    }};

}  // namespace
