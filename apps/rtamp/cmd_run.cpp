// rtamp run — one episode of the reactive loop (episode/episode.hpp) on a scenario,
// in the MuJoCo world or the symbolic one. SIGINT / SIGTERM end the episode cleanly
// (the log gets its end record) with exit code 130 / 143.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "command.hpp"
#include "options.hpp"
#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/episode_log.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void on_signal(int sig) { g_signal.store(sig); }

rtamp::cli::Registrar reg{
    "run",
    "Run one episode: plan, execute through a behavior tree (MuJoCo UR5 or symbolic world), react to the operator",
    [](CLI::App& app) -> rtamp::cli::Action {
      struct Opts {
        std::string scenario, algo = "astar-exp", bt = "online-action", cost = "euclid", log, trees, video, change,
                              world = "mujoco", planning;
        std::uint64_t seed = 1;
        double max_time = 900, rate = 0, failures = 0;
        int cycles = 0;
        bool json = false, quiet = false, random_initial = false, no_operator = false;
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
      rtamp::cli::add_scenario(app, o->scenario)->required();
      app.add_option("--world", o->world, "World: mujoco (simulated UR5) | symbolic (no physics)")
          ->check(CLI::IsMember({"mujoco", "symbolic"}));
      rtamp::cli::add_choice(app, "--algo", o->algo, rtamp::cli::algorithm_choices(), "Search algorithm:");
      app.add_option("--bt", o->bt,
                     "Tree variant: online-action (Algorithm 2, action conditions) | online-state (state "
                     "conditions) | offline (rebuild from scratch)")
          ->check(CLI::IsMember({"online-action", "online-state", "offline"}));
      rtamp::cli::add_choice(app, "--cost", o->cost, rtamp::cli::cost_model_choices(), "Planner motion-cost model:");
      app.add_option("--planning", o->planning,
                     "worker: plan on a thread, charging its time to world time (default for mujoco) | inline: "
                     "plan synchronously, charged nothing, deterministic (default for symbolic)")
          ->check(CLI::IsMember({"worker", "inline"}));
      rtamp::cli::add_seed(app, "--seed", o->seed, "Seed of the episode (operator, perception, random initial layout)");
      app.add_option("--change", o->change, "Add one random intervention: relocate | add | remove")
          ->check(CLI::IsMember({"relocate", "add", "remove"}));
      rtamp::cli::add_real(app, "--rate", o->rate, {0, 100}, "Random interventions per second of world time, of every kind");
      rtamp::cli::add_real(app, "--failures", o->failures, {0, 1}, "Symbolic world: probability that a move fails");
      rtamp::cli::add_integer(app, "--cycles", o->cycles, 0, 1000000,
                              "Recurring tasks (plans that cycle through moves): succeed after K completed cycles "
                              "(0: run until --max-time)");
      app.add_flag("--random-initial", o->random_initial, "Shuffle objects inside their initial locations");
      app.add_flag("--no-operator", o->no_operator, "Ignore the scenario's scripted operator");
      rtamp::cli::add_real(app, "--max-time", o->max_time, {0, 1e7, true}, "Give up after this many seconds of world time");
      app.add_option("--log", o->log, "Write the episode as JSON Lines to FILE");
      app.add_option("--trees", o->trees, "Write the tree as BehaviorTree.CPP XML after each change into DIR");
      app.add_option("--video", o->video, "Record the run to FILE.mp4 (offscreen rendering; mujoco only)");
      app.add_flag("--json", o->json, "Print only the episode's metrics, as one JSON object, on stdout");
      app.add_flag("--quiet", o->quiet, "No timeline");
      return [o]() -> int {
        using namespace rtamp;
        const world::Scenario scenario = world::load_scenario(o->scenario);
        task::validate_task(scenario);  // before any output file is opened or the episode starts
        // Outputs, before ffmpeg or the episode starts, named by their option.
        if (!o->video.empty()) rtamp::cli::check_output_file("--video", o->video);
        if (!o->log.empty()) rtamp::cli::check_output_file("--log", o->log);
        if (!o->trees.empty()) rtamp::cli::check_output_dir("--trees", o->trees);
        episode::EpisodeOptions opt;
        opt.world = o->world == "symbolic" ? episode::WorldKind::Symbolic : episode::WorldKind::MuJoCo;
        opt.algorithm = plan::parse_algorithm(o->algo);
        opt.conditions = o->bt == "online-state" ? exec::ConditionMode::State : exec::ConditionMode::Action;
        opt.reconfiguration = o->bt == "offline" ? exec::Reconfiguration::Offline : exec::Reconfiguration::Online;
        const std::string planning =
            !o->planning.empty() ? o->planning : (opt.world == episode::WorldKind::Symbolic ? "inline" : "worker");
        opt.planning = planning == "inline" ? exec::PlanningMode::Inline : exec::PlanningMode::Worker;
        opt.cost = o->cost;
        opt.seed = o->seed;
        opt.max_time = o->max_time;
        opt.cycles = o->cycles;
        opt.random_rate = o->rate;
        opt.failure_probability = o->failures;
        opt.randomize_initial = o->random_initial;
        opt.scripted_operator = !o->no_operator;
        if (o->change == "relocate") opt.random_change = world::Intervention::Kind::Relocate;
        if (o->change == "add") opt.random_change = world::Intervention::Kind::Add;
        if (o->change == "remove") opt.random_change = world::Intervention::Kind::Remove;
        opt.log_path = o->log;
        opt.tree_dir = o->trees;
        opt.video_path = o->video;
        if (!o->quiet) {
          std::FILE* to = o->json ? stderr : stdout;
          opt.timeline = [to](const std::string& line) {
            std::fputs(line.c_str(), to);
            std::fputc('\n', to);
            std::fflush(to);
          };
        }
        opt.interrupt = &g_signal;
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
