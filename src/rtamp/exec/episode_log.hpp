// The episode log: an EpisodeObserver that writes one JSON object a line
// (JSON Lines) for everything the reactive loop reports — the episode's
// settings and its first task's automaton, new tasks, perceived placements, interventions (applied or refused), steps
// of the observed run with the tracked automaton states, replan requests,
// plans, tree changes, cycles, ticks — and an `end` record with the metrics.
// Every record has "ev" (its kind) and "t" (world seconds, 1e-4 s resolution).
// The file is opened by the constructor as every output is (util/output_file.hpp:
// locked while written, checked; rtamp::OutputError if it cannot be), so a
// bad path is refused before an episode starts; each record is written when
// it happens, so the log is complete up to the last event whatever ends the
// process. A write that fails (a full disk) stops the file, not the episode;
// close() then throws the OutputError naming the file and why.
// Sinks (add_sink) receive every record as well, as the same one-line JSON text
// without the newline — `rtamp serve` streams the log to its pages this way, so
// a page sees exactly what the file holds. A log may have sinks and no file.
// The record kinds are documented in docs/exec.md ("The episode log").
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "rtamp/exec/episode_observer.hpp"
#include "rtamp/util/output_file.hpp"

namespace rtamp::exec {

// The format version the `episode` record carries ("version"); readers refuse a newer one.
inline constexpr int kEpisodeLogVersion = 1;

// The metrics as one JSON object (`indent` < 0: one line).
std::string to_json(const EpisodeMetrics& m, int indent = -1);
// An automaton as the page draws it: {"states": [{id, initial, accepting}],
// "edges": [{from, to, label, accepting}], "state_based": bool} (the `hello`
// message and the log's `task` record).
std::string automaton_json(const automata::Automaton& ba);

class EpisodeLog final : public EpisodeObserver {
 public:
  using Sink = std::function<void(const std::string& record)>;

  // `what` names the file in errors (the option that gave it).
  explicit EpisodeLog(const std::string& path, const std::string& what = "--log");
  // No file: records go to the sinks only.
  EpisodeLog() = default;

  // Every record is also passed to `sink` (on the loop's thread, in order).
  void add_sink(Sink sink) { sinks_.push_back(std::move(sink)); }
  // Writes one more record `object` ("{...}", a JSON object with "ev"), adding
  // "t" as every record has it (e.g. `frame` records of a served episode).
  void record(double t, const std::string& object) { write(t, object); }

  // A number the end record also carries (e.g. the simulator's warnings), read at the end.
  void add_end_field(std::string key, std::function<double()> value) {
    end_fields_.emplace_back(std::move(key), std::move(value));
  }
  // A text the end record also carries as a JSON string (e.g. the tree's final statuses), read at the end.
  void add_end_text(std::string key, std::function<std::string()> value) {
    end_texts_.emplace_back(std::move(key), std::move(value));
  }
  // Where things truly were at the end, which the end record also carries as `truth`
  // (a simulated world perceived imperfectly: its perceived `placement` may differ).
  void set_truth(std::function<world::Placement()> truth) { truth_ = std::move(truth); }
  bool ticks = true;  // write a record per tick

  // Closes the file; throws rtamp::OutputError if any record was lost. Idempotent.
  void close();

  void on_begin(const EpisodeInfo&) override;
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
  void write(double t, const std::string& json_object);

  OutputFile out_;
  std::string lost_;  // why the file stopped (the first failed write), empty: nothing lost
  std::vector<Sink> sinks_;
  std::vector<std::pair<std::string, std::function<double()>>> end_fields_;
  std::vector<std::pair<std::string, std::function<std::string()>>> end_texts_;
  std::function<world::Placement()> truth_;
};

}  // namespace rtamp::exec
