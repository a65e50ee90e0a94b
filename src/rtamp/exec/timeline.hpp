// The readable timeline of an episode: an EpisodeObserver that turns what the
// reactive loop reports into one line per event, stamped with world time
// ("[   4.02 s] operator: add-container t1 -> r1"), and passes each line to a
// sink (the CLI prints them as they happen). Only what a person watching
// needs: plans with their moves and times, tree changes, moves, interventions,
// relocations the robot did not cause, task progress, new tasks, cycles and the end.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "rtamp/exec/episode_observer.hpp"

namespace rtamp::exec {

class Timeline final : public EpisodeObserver {
 public:
  explicit Timeline(std::function<void(const std::string&)> sink) : sink_(std::move(sink)) {}

  void on_action(double t, const char* what, const std::string& action, const std::string& why) override;
  void on_intervention(const WorldEvent&) override;
  void on_perceived(double t, const world::Placement& seen, const world::Placement& before) override;
  void on_things_changed(double t, const std::vector<std::string>& added,
                         const std::vector<std::string>& removed) override;
  void on_progress(double t, const world::Placement& state, const std::vector<std::uint32_t>& states) override;
  void on_handled_by_tree(double t, const std::string& by) override;
  void on_replan_request(double t, const std::string& why) override;
  void on_plan(double t, const PlanEvent&) override;
  void on_tree_change(double t, const ReconfigurationReport&, const PlanTree&, bool deferred) override;
  void on_cycle(double t, int completed) override;
  void on_task(double t, const TaskEvent&) override;
  void on_redirect(double t, const std::string& action, const std::string& rule) override;
  void on_tick(double t, bt::Status, const std::string& running) override;
  void on_end(double t, const EpisodeMetrics&, const world::Placement&) override;

 private:
  void say(double t, const std::string& line);

  std::function<void(const std::string&)> sink_;
  std::string moving_;  // thing of the running move
  world::Placement last_seen_;
  std::vector<std::uint32_t> last_states_;
  bool first_tree_ = true;
};

}  // namespace rtamp::exec
