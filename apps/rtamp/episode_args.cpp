#include "episode_args.hpp"

#include "options.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::cli {

void add_episode_options(CLI::App& app, EpisodeArgs& o, const std::string& log_help) {
  add_scenario(app, o.scenario)->required();
  add_choice(app, "--world", o.world, choices_of(episode::worlds()), "World:");
  add_choice(app, "--algo", o.algo, algorithm_choices(), "Search algorithm:");
  add_choice(app, "--bt", o.bt, choices_of(exec::tree_variants()), "Tree variant:");
  add_choice(app, "--cost", o.cost, cost_model_choices(), "Planner motion-cost model:");
  add_choice(app, "--planning", o.planning, choices_of(exec::planning_modes()),
             "Planning (default: worker for mujoco, inline for symbolic):");
  add_seed(app, "--seed", o.seed, "Seed of the episode (the person, perception, random initial layout)");
  add_choice(app, "--change", o.change, choices_of(world::random_change_kinds()),
             "Add one random intervention at a random time in 2-20 s:");
  add_real(app, "--rate", o.rate, {0, 100},
           "Random interventions per second of world time, of every kind (docs/person.md)");
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
  opt.world = parse_name(episode::worlds(), o.world, "world");
  opt.algorithm = plan::parse_algorithm(o.algo);
  const exec::TreeVariant bt = parse_name(exec::tree_variants(), o.bt, "tree variant");
  opt.conditions = bt.conditions;
  opt.reconfiguration = bt.reconfiguration;
  opt.planning = !o.planning.empty() ? parse_name(exec::planning_modes(), o.planning, "planning mode")
                 : opt.world == episode::WorldKind::Symbolic ? exec::PlanningMode::Inline
                                                             : exec::PlanningMode::Worker;
  opt.cost = o.cost;
  opt.seed = o.seed;
  opt.max_time = o.max_time;
  opt.cycles = o.cycles;
  opt.random_rate = o.rate;
  opt.failure_probability = o.failures;
  opt.randomize_initial = o.random_initial;
  opt.scripted_operator = !o.no_operator;
  if (!o.change.empty()) opt.random_change = parse_name(world::random_change_kinds(), o.change, "change");
  opt.log_path = o.log;
  opt.tree_dir = o.trees;
  return opt;
}

}  // namespace rtamp::cli
