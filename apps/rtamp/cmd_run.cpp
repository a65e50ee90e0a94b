// rtamp run — one episode of the reactive loop (episode/episode.hpp) on a scenario,
// in the MuJoCo world or the symbolic one. SIGINT / SIGTERM end the episode cleanly
// (the log gets its end record) with exit code 130 / 143.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "episode_args.hpp"
#include "options.hpp"
#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/episode_log.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/util/text_file.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void on_signal(int sig) { g_signal.store(sig); }

rtamp::cli::Registrar reg{
    "run",
    "Run one episode: plan, execute through a behavior tree (MuJoCo UR5 or symbolic world), react to the operator",
    [](CLI::App& app) -> rtamp::cli::Action {
      struct Opts : rtamp::cli::EpisodeArgs {
        std::string video;
        bool json = false, quiet = false;
      };
      auto o = std::make_shared<Opts>();
      app.description(
          "Run one episode of rtamp's reactive loop (the paper's Algorithm 1) on SCENARIO (a YAML file or a\n"
          "built-in name): translate the task, plan, build the behavior tree, execute it while the operator\n"
          "intervenes, track the task's progress along what actually happens, replan and reconfigure the tree\n"
          "when needed. --world mujoco (default) runs the simulated UR5; --world symbolic runs a discrete-event\n"
          "world with no physics (milliseconds an episode; docs/symbolic-world.md). Prints a timeline (world\n"
          "time) unless --quiet; --json prints only the metrics as JSON on stdout (the timeline then goes to\n"
          "stderr). Exit code 0 if the task was done, 1 if the episode ended otherwise, 2 on bad input,\n"
          "130 / 143 when interrupted by SIGINT / SIGTERM.");
      rtamp::cli::add_episode_options(app, *o, "Write the episode as JSON Lines to FILE");
      app.add_option("--video", o->video, "Record the run to FILE.mp4 (offscreen rendering; mujoco only)");
      app.add_flag("--json", o->json, "Print only the episode's metrics, as one JSON object, on stdout");
      app.add_flag("--quiet", o->quiet, "No timeline");
      return [o]() -> int {
        using namespace rtamp;
        const world::Scenario scenario = world::load_scenario(o->scenario);
        task::validate_task(scenario);  // before any output file is opened or the episode starts
        // Outputs, before ffmpeg or the episode starts, named by their option.
        if (!o->video.empty()) rtamp::cli::check_output_file("--video", o->video);
        episode::EpisodeOptions opt = rtamp::cli::episode_options(*o);
        {  // no output is an input or another output (by device and inode), each writable
          FileSet files;
          if (path_exists(o->scenario)) files.input("SCENARIO", o->scenario);
          if (!opt.outputs.log.empty()) files.output("--log", opt.outputs.log);
          if (!opt.outputs.mcap.empty()) files.output("--mcap", opt.outputs.mcap);
          if (!o->video.empty()) files.output("--video", o->video);
        }
        if (!opt.outputs.log.empty()) rtamp::cli::check_output_file("--log", opt.outputs.log);
        if (!opt.outputs.mcap.empty()) rtamp::cli::check_output_file("--mcap", opt.outputs.mcap);
        if (!opt.outputs.trees.empty()) rtamp::cli::check_output_dir("--trees", opt.outputs.trees);
        opt.outputs.video = o->video;
        if (!o->quiet) {
          std::FILE* to = o->json ? stderr : stdout;
          opt.outputs.timeline = [to](const std::string& line) {
            std::fputs(line.c_str(), to);
            std::fputc('\n', to);
            std::fflush(to);
          };
        }
        opt.loop.interrupt = &g_signal;
        std::signal(SIGINT, on_signal);
        std::signal(SIGTERM, on_signal);
        const episode::EpisodeMetrics m = episode::run_episode(scenario, opt);
        std::signal(SIGINT, SIG_DFL);
        std::signal(SIGTERM, SIG_DFL);
        if (o->json) {
          std::cout << exec::to_json(m, 2) << '\n';
        } else {
          const std::string completion = m.completion_time ? format_number(*m.completion_time) + " s" : "none";
          std::printf("\n%s: %s\n  completion %s (world time), motion cost %s m, %d replans (%s total), "
                      "first plan %s, %zu tree changes, %d interventions (%d applied, %d refused)%s, "
                      "real-time factor %sx\n",
                      m.success ? "SUCCESS" : "FAILURE", escape_text(m.reason).c_str(), completion.c_str(),
                      format_number(m.motion_cost).c_str(), m.replans, format_seconds(m.replan_seconds).c_str(),
                      format_seconds(m.first_plan_seconds).c_str(), m.tree_changes, m.interventions,
                      m.interventions_applied, m.interventions_refused,
                      m.cycles > 0 ? (", " + std::to_string(m.cycles) + " cycles").c_str() : "",
                      format_number(m.real_time_factor, 3).c_str());
        }
        if (m.end == exec::EndReason::Interrupted) return g_signal.load() == SIGTERM ? 143 : 130;
        return m.success ? 0 : 1;
      };
    }};

}  // namespace
