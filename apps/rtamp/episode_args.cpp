#include "episode_args.hpp"

#include "options.hpp"
#include "rtamp/plan/registry.hpp"

namespace rtamp::cli {

void add_episode_options(CLI::App& app, EpisodeArgs& o, const std::string& log_help) {
  add_scenario(app, o.scenario)->required();
  app.add_option("--world", o.world, "World: mujoco (simulated UR5) | symbolic (no physics)")
      ->check(CLI::IsMember({"mujoco", "symbolic"}));
  add_choice(app, "--algo", o.algo, algorithm_choices(), "Search algorithm:");
  app.add_option("--bt", o.bt,
                 "Tree variant: online-action (Algorithm 2, action conditions) | online-state (state "
                 "conditions) | offline (rebuild from scratch)")
      ->check(CLI::IsMember({"online-action", "online-state", "offline"}));
  add_choice(app, "--cost", o.cost, cost_model_choices(), "Planner motion-cost model:");
  app.add_option("--planning", o.planning,
                 "worker: plan on a thread, charging its time to world time (default for mujoco) | inline: "
                 "plan synchronously, charged nothing, deterministic (default for symbolic)")
      ->check(CLI::IsMember({"worker", "inline"}));
  add_seed(app, "--seed", o.seed, "Seed of the episode (operator, perception, random initial layout)");
  app.add_option("--change", o.change, "Add one random intervention: relocate | add | remove")
      ->check(CLI::IsMember({"relocate", "add", "remove"}));
  add_real(app, "--rate", o.rate, {0, 100}, "Random interventions per second of world time, of every kind");
  add_real(app, "--failures", o.failures, {0, 1}, "Symbolic world: probability that a move fails");
  add_integer(app, "--cycles", o.cycles, 0, 1000000,
              "Recurring tasks (plans that cycle through moves): succeed after K completed cycles "
              "(0: run until --max-time)");
  app.add_flag("--random-initial", o.random_initial, "Shuffle objects inside their initial locations");
  app.add_flag("--no-operator", o.no_operator, "Ignore the scenario's scripted operator");
  add_real(app, "--max-time", o.max_time, {0, 1e7, true}, "Give up after this many seconds of world time");
  app.add_option("--log", o.log, log_help);
  app.add_option("--trees", o.trees, "Write the tree as BehaviorTree.CPP XML after each change into DIR");
}

episode::EpisodeOptions to_episode_options(const EpisodeArgs& o) {
  episode::EpisodeOptions opt;
  opt.world = o.world == "symbolic" ? episode::WorldKind::Symbolic : episode::WorldKind::MuJoCo;
  opt.algorithm = plan::parse_algorithm(o.algo);
  opt.conditions = o.bt == "online-state" ? exec::ConditionMode::State : exec::ConditionMode::Action;
  opt.reconfiguration = o.bt == "offline" ? exec::Reconfiguration::Offline : exec::Reconfiguration::Online;
  const std::string planning =
      !o.planning.empty() ? o.planning : (opt.world == episode::WorldKind::Symbolic ? "inline" : "worker");
  opt.planning = planning == "inline" ? exec::PlanningMode::Inline : exec::PlanningMode::Worker;
  opt.cost = o.cost;
  opt.seed = o.seed;
  opt.max_time = o.max_time;
  opt.cycles = o.cycles;
  opt.random_rate = o.rate;
  opt.failure_probability = o.failures;
  opt.randomize_initial = o.random_initial;
  opt.scripted_operator = !o.no_operator;
  if (o.change == "relocate") opt.random_change = world::Intervention::Kind::Relocate;
  if (o.change == "add") opt.random_change = world::Intervention::Kind::Add;
  if (o.change == "remove") opt.random_change = world::Intervention::Kind::Remove;
  opt.log_path = o.log;
  opt.tree_dir = o.trees;
  return opt;
}

}  // namespace rtamp::cli
