// rtamp run — one episode of the reactive loop (exec/episode.hpp) on a scenario.
#include <iostream>

#include "command.hpp"
#include "rtamp/exec/episode.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

rtamp::cli::Registrar reg{
    "run",
    "Run one episode: plan, execute through a behavior tree on the simulated UR5, react to the operator",
    [](CLI::App& app) -> rtamp::cli::Action {
      struct Opts {
        std::string scenario, algo = "astar-exp", bt = "online-action", cost = "euclid", log, trees, video, change;
        std::uint64_t seed = 1;
        double max_time = 900;
        bool json = false, quiet = false, random_initial = false, no_operator = false;
      };
      auto o = std::make_shared<Opts>();
      app.description(
          "Run one episode of rtamp's reactive loop (the paper's Algorithm 1) on SCENARIO (a YAML file or a\n"
          "built-in name: 3-block, 3-block-tray): translate the task, plan, build the behavior tree, execute\n"
          "it on the simulated UR5 while the scenario's operator intervenes, replan and reconfigure the tree\n"
          "when needed. Prints a timeline (simulated time) unless --quiet; --json prints the metrics.");
      app.add_option("scenario", o->scenario, "Scenario file or built-in name")->required();
      app.add_option("--algo", o->algo, "Search: dijkstra | astar | astar-exp (A* with experience)")
          ->check(CLI::IsMember({"dijkstra", "astar", "astar-exp"}));
      app.add_option("--bt", o->bt,
                     "Tree variant: online-action (Algorithm 2, action conditions) | online-state (state "
                     "conditions) | offline (rebuild from scratch)")
          ->check(CLI::IsMember({"online-action", "online-state", "offline"}));
      app.add_option("--cost", o->cost, "Planner motion cost: euclid | region | unit | ik (UR5 skill paths)")
          ->check(CLI::IsMember({"euclid", "region", "unit", "ik"}));
      app.add_option("--seed", o->seed, "Seed of the episode (operator, perception, random initial layout)");
      app.add_option("--change", o->change, "Add one random intervention: relocate | add | remove")
          ->check(CLI::IsMember({"relocate", "add", "remove"}));
      app.add_flag("--random-initial", o->random_initial, "Shuffle objects inside their initial locations");
      app.add_flag("--no-operator", o->no_operator, "Ignore the scenario's scripted operator");
      app.add_option("--max-time", o->max_time, "Give up after this many seconds of simulated time");
      app.add_option("--log", o->log, "Write the episode as JSON Lines to FILE");
      app.add_option("--trees", o->trees, "Write the tree as BehaviorTree.CPP XML after each change into DIR");
      app.add_option("--video", o->video, "Record the run to FILE.mp4 (offscreen rendering)");
      app.add_flag("--json", o->json, "Print the episode's metrics as one JSON object at the end");
      app.add_flag("--quiet", o->quiet, "No timeline");
      return [o]() -> int {
        using namespace rtamp;
        const world::Scenario scenario = world::load_scenario(o->scenario);
        exec::EpisodeOptions opt;
        opt.algorithm = o->algo == "dijkstra" ? plan::Algorithm::Dijkstra
                        : o->algo == "astar"  ? plan::Algorithm::AStar
                                              : plan::Algorithm::AStarExperience;
        opt.conditions = o->bt == "online-state" ? exec::ConditionMode::State : exec::ConditionMode::Action;
        opt.reconfiguration = o->bt == "offline" ? exec::Reconfiguration::Offline : exec::Reconfiguration::Online;
        opt.cost = o->cost;
        opt.seed = o->seed;
        opt.max_time = o->max_time;
        opt.randomize_initial = o->random_initial;
        opt.scripted_operator = !o->no_operator;
        if (o->change == "relocate") opt.random_change = world::Intervention::Kind::Relocate;
        if (o->change == "add") opt.random_change = world::Intervention::Kind::Add;
        if (o->change == "remove") opt.random_change = world::Intervention::Kind::Remove;
        opt.log_path = o->log;
        opt.tree_dir = o->trees;
        opt.video_path = o->video;
        if (!o->quiet) opt.timeline = [](const std::string& line) { std::cout << line << '\n' << std::flush; };
        const exec::EpisodeMetrics m = exec::run_episode(scenario, opt);
        if (o->json) {
          std::cout << exec::to_json(m).dump(2) << '\n';
        } else {
          std::printf("\n%s: %s\n  completion %.2f s (simulated), motion cost %.3f m, %d replans (%.1f us total), "
                      "first plan %.1f us, %zu tree changes, %d interventions, real-time factor %.1fx\n",
                      m.success ? "SUCCESS" : "FAILURE", m.reason.c_str(), m.completion_time, m.motion_cost,
                      m.replans, m.replan_seconds * 1e6, m.first_plan_seconds * 1e6, m.tree_changes,
                      m.interventions, m.real_time_factor);
        }
        return m.success ? 0 : 1;
      };
    }};

}  // namespace
