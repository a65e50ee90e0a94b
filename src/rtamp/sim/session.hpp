// A simulated episode driven by an explicit action list — what `rtamp sim SCENARIO
// --do "move o1 r3; move r3 r2"` runs, and a facade bundling simulation, controller,
// skill runner, perception and operator for callers (tests, benchmarks, the exec layer).
//
// Action list syntax: actions separated by ';' (blank ones ignored), words by spaces:
//   move THING LOCATION   pick THING, place it in LOCATION (region or tray)
//   pick THING            place LOCATION (the held thing)
//   wait SECONDS          let the simulation run (the operator acts meanwhile)
// Errors in the list are rtamp::Error with the 1-based column in the list text.
// Names are checked before anything moves (sim/action_check.hpp, the rules of
// every entry point): run() checks the whole list and execute() its action
// against the running simulation's names (the scenario's, and those an
// operator added since), so a bad list moves nothing. Each action runs to SUCCESS or FAILURE; a failed action does not stop the list (the
// next one starts from whatever state the world is in), so outcomes are reported per
// action. The person's interventions (world/person.hpp: scripted and random) are
// applied between physics steps whenever they are due. Rendering happens only when a video is being recorded.
// Determinism: the same scenario, options and seed give the same episode.
#pragma once

#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/sim/controller.hpp"
#include "rtamp/sim/operator.hpp"
#include "rtamp/sim/perception.hpp"
#include "rtamp/sim/renderer.hpp"
#include "rtamp/sim/skill_runner.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/person.hpp"

namespace rtamp::sim {

struct SimAction {
  enum class Kind { Move, Pick, Place, Wait };
  Kind kind = Kind::Move;
  std::string thing;     // Move, Pick
  std::string location;  // Move, Place
  double seconds = 0;    // Wait
  std::string text;      // as written
  int column = 1;        // where it starts in the list (1-based)
};

std::vector<SimAction> parse_actions(const std::string& text);

struct SessionOptions {
  SimOptions sim;
  SkillRunnerOptions skills;
  ControllerOptions controller;
  PerceptionOptions perception;
  // A person acting while the actions run (its script, random interventions);
  // an episode leaves it empty and drives the world with exec::PersonWorld.
  world::PersonOptions person;
  bool scripted_operator = false;  // the person also applies the scenario's interventions
  std::uint64_t seed = 1;          // seeds perception and the person (overrides theirs)
  std::string video_path;          // record the run when set
  int video_fps = 30;
  RenderOptions render;
};

struct SessionReport {
  std::vector<ActionResult> actions;
  std::vector<OperatorEvent> interventions;
  Percept final_percept;
  double sim_time = 0;   // s of simulated time
  double wall_time = 0;  // s of wall-clock time for the actions
  double real_time_factor() const { return wall_time > 0 ? sim_time / wall_time : 0; }
  Warnings warnings;
  int video_frames = 0;
};

class Session {
 public:
  Session(const world::Scenario& scenario, SessionOptions options = {});
  ~Session();

  Simulation& sim() { return sim_; }
  const Simulation& sim() const { return sim_; }
  Controller& controller() { return controller_; }
  SkillRunner& skills() { return runner_; }
  Perception& perception() { return perception_; }
  const Perception& perception() const { return perception_; }
  Operator& op() { return operator_; }
  // Every present thing where it truly is (noise-free perception; held: "hand").
  world::Placement true_placement();

  // Runs one action to completion. Throws rtamp::Error ("action:1:COL: ...",
  // column in a.text) before anything moves if it names an unknown thing or
  // location, or waits for no duration in 0..3600 s.
  ActionResult execute(const SimAction& a);
  // Runs a list and reports; `on_action` (optional) sees each result as it
  // finishes. Checks every action first: on a bad one throws rtamp::Error
  // ("actions:1:COL: ...", column in the actions' texts joined by "; ") and
  // nothing has moved.
  SessionReport run(const std::vector<SimAction>& actions,
                    const std::function<void(const ActionResult&)>& on_action = {});
  // The names actions may use now: the scenario's (with its script's when the
  // scripted operator runs) and every thing added to the simulation since.
  world::Vocabulary vocabulary() const;
  // Renders the current scene to a PNG (makes a renderer if none is open).
  void snapshot(const std::string& png_path);

 private:
  void after_step();
  ActionResult run_action(const SimAction& a);

  SessionOptions options_;
  Simulation sim_;
  Controller controller_;
  SkillRunner runner_;
  Perception perception_;
  Perception truth_;  // noise-free
  Operator operator_;
  world::Person person_;
  std::vector<OperatorEvent> events_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<VideoWriter> video_;
  std::vector<std::uint8_t> frame_;
  double next_frame_ = 0;
  std::function<void()> on_step_;
};

}  // namespace rtamp::sim
