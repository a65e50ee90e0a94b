// The reactive loop on your own robot: a hand-written exec::World (the one
// interface rtamp needs from a robot and its perception, exec/world.hpp)
// driven by exec::ReactiveLoop (the paper's Algorithm 1) on a sequencing task.
//
// TableWorld is the smallest honest world: every thing sits in a named
// location; a move takes one second to pick (the thing stays where it is) and
// one to carry and place (the thing is in the hand), then it is at its target.
// It is a discrete-event world: next_event_time() tells the loop when the
// running move next changes phase, so the loop jumps there instead of ticking.
// A real robot would start its pick-and-place in start(), report its progress
// in poll() and its perception in observe().
//
// The task F (o1_in_r3 & F G all_in_r2): first bring o1 to r3, then all blocks
// to r2 and keep them there. The program checks from the observed run itself
// that o1 was in r3 before every block was in r2, and exits 1 if not.
#include <iostream>
#include <limits>
#include <map>
#include <string>

#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

const char* kScenario = R"yaml(
name: own-world
robot: {model: ur5, base: [0, 0, 0], yaw: 0}
regions:
  - {name: r1, center: [0.40, 0.32, 0], size: [0.30, 0.30], capacity: 4}
  - {name: r2, center: [0.40, -0.32, 0], size: [0.30, 0.30], capacity: 4}
  - {name: r3, center: [0.60, 0.00, 0], size: [0.20, 0.20], capacity: 4}
objects:
  - {name: o1, class: block, position: [0.35, 0.32, 0], size: [0.04, 0.04, 0.04]}
  - {name: o2, class: block, position: [0.45, 0.32, 0], size: [0.04, 0.04, 0.04]}
propositions:
  o1_in_r3: "o1 in r3"
  all_in_r2: "all block in r2"
task: "F (o1_in_r3 & F G all_in_r2)"
)yaml";

class TableWorld final : public rtamp::exec::World {
 public:
  TableWorld() : where_{{"o1", "r1"}, {"o2", "r1"}} {}

  double time() const override { return now_; }
  void advance(double dt) override { now_ += dt; }
  double next_event_time() const override {
    if (status_ != rtamp::exec::MoveStatus::Running) return std::numeric_limits<double>::infinity();
    return now_ < started_ + 1.0 ? started_ + 1.0 : started_ + 2.0;
  }

  rtamp::world::Placement observe() override {
    settle();
    rtamp::world::Placement p;
    for (const auto& [thing, location] : where_) p.set(thing, location, "block");
    if (status_ == rtamp::exec::MoveStatus::Running && now_ >= started_ + 1.0) p.set(move_.thing, "hand", "block");
    return p;
  }

  void start(const rtamp::exec::Move& m) override {
    std::cout << "[" << now_ << " s] start " << m.action << "\n";
    move_ = m;
    started_ = now_;
    status_ = rtamp::exec::MoveStatus::Running;
  }
  rtamp::exec::MoveStatus poll(std::string* why) override {
    settle();
    if (status_ == rtamp::exec::MoveStatus::Failed && why) *why = "halted";
    return status_;
  }
  void halt() override {  // the thing never left its source (or is put back there)
    if (status_ == rtamp::exec::MoveStatus::Running) status_ = rtamp::exec::MoveStatus::Failed;
  }
  bool busy() override { return false; }
  std::string hand() const override { return hand_; }

 private:
  // A running move whose two seconds have passed ends: its thing is at the target.
  void settle() {
    if (status_ != rtamp::exec::MoveStatus::Running || now_ < started_ + 2.0) return;
    where_[move_.thing] = move_.to;
    hand_ = move_.to;
    status_ = rtamp::exec::MoveStatus::Succeeded;
  }

  double now_ = 0, started_ = 0;
  std::map<std::string, std::string> where_;
  std::string hand_;
  rtamp::exec::Move move_;
  rtamp::exec::MoveStatus status_ = rtamp::exec::MoveStatus::Idle;
};

}  // namespace

int main() {
  const rtamp::world::Scenario scenario = rtamp::world::parse_scenario(kScenario, "own_world.cpp");
  TableWorld world;
  rtamp::exec::LoopOptions options;
  options.planning = rtamp::exec::PlanningMode::Inline;  // deterministic: plans cost no world time
  options.world_name = "table";
  options.max_time = 120;
  rtamp::exec::ReactiveLoop loop(world, scenario, options);
  const rtamp::exec::EpisodeMetrics& m = loop.run();
  std::cout << rtamp::exec::to_string(m.end) << ": " << m.reason << " after " << m.world_time << " s, "
            << m.actions_succeeded << " moves\n";

  // The order the task asks for, read from the run the loop observed.
  bool o1_was_in_r3 = false, in_order = false;
  for (const auto& state : loop.observed_run()) {
    if (*state.location_of("o1") == "r3") o1_was_in_r3 = true;
    if (o1_was_in_r3 && *state.location_of("o1") == "r2" && *state.location_of("o2") == "r2") in_order = true;
  }
  if (!m.success || !in_order) {
    std::cerr << "own_world: the task was not achieved in order\n";
    return 1;
  }
  std::cout << "o1 visited r3, then every block stayed in r2\n";
  return 0;
}
