#include "episode_args.hpp"

#include "options.hpp"
#include "rtamp/plan/registry.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::cli {

std::vector<Choice> world_choices() {
  std::vector<Choice> out;
  for (const auto& w : episode::worlds()) out.push_back({w.name, w.description});
  return out;
}

std::vector<Choice> perception_choices() {
  return {{"truth", "the simulation's poses"},
          {"camera", "mujoco: RGB-D frames of the scenario's primary camera, segmented and fitted from pixels, "
                     "kept in a belief (docs/perception.md); symbolic: the errors that pipeline was measured to make "
                     "(late changes; docs/symbolic-world.md)"}};
}

void add_episode_options(CLI::App& app, EpisodeArgs& a, const std::string& log_help) {
  episode::EpisodeOptions& o = a.episode;
  exec::LoopOptions& loop = o.loop;
  add_scenario(app, a.scenario)->required();
  add_choice(app, "--world", o.world, world_choices(), "World:");
  add_choice_with(
      app, "--algo", algorithm_choices(), plan::algorithm_info(loop.planner.algorithm).name,
      [&loop](const std::string& s) { loop.planner.algorithm = plan::parse_algorithm(s); }, "Search algorithm:");
  add_choice_with(
      app, "--bt", choices_of(exec::tree_variants()), "online-action",
      [&loop](const std::string& s) {
        const exec::TreeVariant v = parse_name(exec::tree_variants(), s, "tree variant");
        loop.conditions = v.conditions;
        loop.reconfiguration = v.reconfiguration;
      },
      "Tree variant:");
  add_choice(app, "--cost", loop.planner.cost, cost_model_choices(), "Planner motion-cost model:");
  a.planning = add_choice_with(
      app, "--planning", choices_of(exec::planning_modes()), "the world's",
      [&loop](const std::string& s) { loop.planning = parse_name(exec::planning_modes(), s, "planning mode"); },
      "Planning (default: the world's — worker for mujoco, inline for symbolic):");
  add_seed(app, "--seed", o.seed, "Seed of the episode (the world, the person, the random initial layout)");
  add_choice_with(
      app, "--change", choices_of(world::random_change_kinds()), "none",
      [&o](const std::string& s) {
        o.person.change = world::RandomChange{parse_name(world::random_change_kinds(), s, "change")};
      },
      "Add one random intervention at a random time in 2-20 s:");
  add_real(app, "--rate", o.person.rate, {0, 100},
           "Random interventions per second of world time, of every kind (docs/person.md)");
  add_real(app, "--failures", o.world_settings.failure_probability, {0, 1},
           "Symbolic world: probability that a move fails");
  add_choice(app, "--perception", o.world_settings.perception, perception_choices(), "How the robot perceives:");
  add_perception_cameras(app, o.world_settings.perception_cameras);
  add_integer(app, "--cycles", loop.cycles, 0, 1000000,
              "Recurring tasks (plans that cycle through moves): succeed after K completed cycles "
              "(0: run until --max-time)");
  add_new_task(app, loop.task_changes);
  app.add_flag("--random-initial", o.randomize_initial, "Shuffle objects inside their initial locations");
  app.add_flag("--no-operator{false}", o.scripted_operator, "Ignore the scenario's scripted operator");
  add_real(app, "--max-time", loop.max_time, {0, 1e7, true}, "Give up after this many seconds of world time");
  app.add_option("--log", o.outputs.log, log_help);
  app.add_option("--mcap", o.outputs.mcap,
                 "Also write the episode as MCAP to FILE (every log record on /rtamp/log, and the scene, arm, plan, "
                 "tree, automaton, interventions, replans and timeline on Foxglove channels; docs/formats.md)");
  add_choice_with(
      app, "--mcap-compression", mcap_compression_choices(), "zstd",
      [&o](const std::string& s) { o.outputs.mcap_compression = episode::parse_mcap_compression(s); },
      "Compression of the --mcap file's chunks:");
  add_choice_with(
      app, "--mcap-profile", mcap_profile_choices(), "json",
      [&o](const std::string& s) { o.outputs.mcap_profile = episode::parse_mcap_profile(s); },
      "Profile of the --mcap file (docs/formats.md):");
  add_mcap_image_period(app, o.outputs.mcap_image_period);
  app.add_option("--trees", o.outputs.trees, "Write the tree as BehaviorTree.CPP XML after each change into DIR");
}

CLI::Option* add_perception_cameras(CLI::App& app, std::vector<std::string>& target) {
  return app.add_option("--perception-cameras", target,
                        "With --perception camera: the scenario's cameras that perceive, comma-separated, each at its "
                        "own rate into one belief (e.g. overhead,wrist; default: the primary camera; "
                        "docs/perception.md)")
      ->delimiter(',')
      ->type_name("NAMES");
}

CLI::Option* add_mcap_image_period(CLI::App& app, double& target) {
  return add_real(app, "--mcap-image-period", target, {0, std::numeric_limits<double>::max(), false, true, "no images"},
                  "With --perception camera: world seconds between the camera images written to the MCAP file, with "
                  "their detection boxes (/camera/NAME/image and /annotations; 0: every frame; default 1)");
}

episode::EpisodeOptions episode_options(const EpisodeArgs& a) {
  episode::EpisodeOptions o = a.episode;
  if (!a.planning || a.planning->count() == 0) o.loop.planning = episode::find_world(o.world).planning;
  return o;
}

}  // namespace rtamp::cli
