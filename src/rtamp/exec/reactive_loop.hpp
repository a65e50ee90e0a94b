// The reactive loop of the paper's Algorithm 1, for any task and any world:
// perceive → track the task's progress → decide (the tree can go on / update
// the TS / replan) → reconfigure the tree (Algorithm 2) → tick. It talks to
// the world only through exec::World (world.hpp) and reports everything to
// attached EpisodeObservers; it links no simulator.
//
// One step() is one iteration: let time pass (a tick period, or — in a
// discrete-event world — up to the next event, see Liveness), observe,
// decide, tick.
//
// The observed run. The loop keeps the run that actually happened as a
// sequence of symbolic states (where every thing is; a held thing counts as
// still at its source until it is put down, a thing briefly outside every
// location keeps its last location). A new state enters the run whenever that
// changes, by the robot or by a person; additions and removals are steps too.
// plan::TaskProgress tracks the Büchi states consistent with the run
// (stuttering — the robot staying in a state — is free: the run may repeat a
// state any number of times, which is how plans with `stay` steps and `X`
// are read at execution time; for X-free tasks this changes nothing).
//
// Planning. Every plan and replan starts from (the current state, the tracked
// automaton states). While a move runs and its thing is still where the move
// expects, the plan starts from the state after that move (the move is not
// cut) — unless the rule book of space (world/space_rules.hpp) would refuse
// that move's place now (a person filled its destination during the carry):
// the move cannot finish, so the plan starts from the current state (its
// thing back where it was picked) and the move is halted (the world puts the
// thing back; on_redirect says why). No plan starts from a state that breaks
// the rule book because a running move was assumed finished. The task is done when every step of the tree is done and staying in
// the current state forever satisfies the task from a tracked state; a task
// whose plans cycle through moves (patrolling) counts completed cycles — a
// cycle counts when the tree has run the whole plan and the run since the
// previous count, repeated forever, satisfies the task — and ends after
// `cycles` of them (0: runs until max_time). If the observed history leaves no
// way to satisfy the task (no tracked state can reach acceptance), the
// episode ends with EndReason::Unsatisfiable at once.
//
// A new task (the paper's "new temporal logic specifications";
// docs/exec.md "A new task"): scheduled in LoopOptions::task_changes, or
// given at run time by set_task (thread-safe, through an inbox). It takes
// effect at the first step at or after its time: the planner translates it
// (keeping the TS and the motion-cost cache), task progress restarts at the
// new automaton's initial state on the current state, and the run is judged
// for it from that state on (task_from()). A running move is finished unless
// finishing it would leave the new task no accepting future: then it is
// halted (the world puts its thing back) and the redirection is reported
// (on_redirect, with the rule). A task the current state already satisfies
// ends the episode (task done), one it can no longer satisfy ends it
// (unsatisfiable), naming the task change; otherwise the loop replans and
// Algorithm 2 keeps the subtrees the new plan shares. Cycles count for the
// task in force. A task change the loop refuses (a proposition redefined
// since it was checked) is reported and the episode goes on.
//
// Failures. A move that failed undisturbed is remembered with the state it
// started from: every plan from that state avoids it (Planner::forbid_move)
// while some plan can, and when max_failures_per_move failures of the same
// move from the same state have happened — whatever succeeded in between —
// the episode gives up, naming the move and the rule.
//
// Liveness. Time passes only after the tree has been ticked on the present:
// the first tick comes before any time passes, a new plan or a due tree
// change ticks at once, and a discrete-event world is advanced at most one
// tick period while the arm is free (never past a moment the robot could act).
//
// Invariants: at most one move runs; the tree is ticked only while the world
// is not busy; observers see every intervention, plan and tree change; on
// every way out — success, failure, stop() or an exception — on_end is called
// exactly once with complete metrics. At the end a running tree is halted
// (every node INVALID); a finished one keeps its last tick's statuses.
#pragma once

#include <atomic>
#include <chrono>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/exec/episode_metrics.hpp"
#include "rtamp/exec/episode_observer.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/exec/world.hpp"
#include "rtamp/exec/world_runner.hpp"
#include "rtamp/plan/planner.hpp"
#include "rtamp/plan/task_progress.hpp"
#include "rtamp/task/labeling.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

// How the planner's time is paid.
enum class PlanningMode {
  Worker,  // on a worker thread while the tree ticks; a plan is used once its
           // measured wall time has passed in world time (the paper's setting)
  Inline,  // synchronously, charged nothing: deterministic (tests, symbolic batches)
};
const NameTable<PlanningMode>& planning_modes();  // worker inline

struct LoopOptions {
  plan::PlannerOptions planner;                     // algorithm, cost model, limits
  ConditionMode conditions = ConditionMode::Action;
  Reconfiguration reconfiguration = Reconfiguration::Online;
  PlanningMode planning = PlanningMode::Worker;
  double max_time = 900;       // s of world time before giving up
  double tick_period = 0.02;   // s between ticks (continuous worlds)
  int max_failures_per_move = 5;  // undisturbed failures of one move from one state before giving up
  double outside_grace = 3;    // s a thing may be outside every location
  // s the perceived placement must have stayed the same (but for the robot's
  // own moves) before the task is judged done or impossible, or the last
  // cycle ends: perception that may still be catching up with a change (a
  // camera's belief) settles first. 0: at once. Never settled while the world
  // is confirming a change it has seen (World::confirming).
  double settle = 0;
  int cycles = 0;              // recurring tasks: succeed after this many cycles of the task in force (0: never)
  // New tasks at world times (the scenario's operator script, --new-task),
  // checked by the constructor (task::validate_task_changes; each time before
  // max_time) and taken in order at the first step at or after each time.
  std::vector<world::TaskChange> task_changes;
  std::uint64_t seed = 0;      // reported in the metrics
  std::string world_name;      // reported to observers ("mujoco", "symbolic", ...)
  // Polled every step; nonzero ends the episode (EndReason::Interrupted). For
  // signal handlers, which may only store to a lock-free atomic.
  const std::atomic<int>* interrupt = nullptr;
};

// The loop's numbers, checked before anything runs (a NaN time limit or a
// zero tick would run forever): throws rtamp::Error "loop option NAME: RULE,
// found VALUE" unless max_time > 0 (inf: no limit), tick_period finite > 0,
// outside_grace and settle finite >= 0, max_failures_per_move >= 1, cycles >= 0.
// Returns `o`. The loop's constructor calls it; callers that open outputs
// first (episode::run_episode) call it before.
const LoopOptions& check_loop_options(const LoopOptions& o);

// New tasks for an episode of `s` that ends at `max_time`: sorted by time
// (stable), each checked on the scenario the ones before it leave
// (task::validate_task_changes) and due before max_time. Returns them sorted;
// throws rtamp::Error naming the first bad one. The constructor calls it.
std::vector<world::TaskChange> check_task_schedule(const world::Scenario& s, std::vector<world::TaskChange> changes,
                                                  double max_time);

class ReactiveLoop {
 public:
  // Translates the task (rtamp::Error on a bad task, or on options out of
  // range: check_loop_options). `world` must outlive the loop.
  ReactiveLoop(World& world, const world::Scenario& scenario, LoopOptions options);
  ~ReactiveLoop();
  ReactiveLoop(const ReactiveLoop&) = delete;
  ReactiveLoop& operator=(const ReactiveLoop&) = delete;

  // Observers must outlive the loop (or the episode).
  void add_observer(EpisodeObserver& o) { observers_.push_back(&o); }

  // One iteration; false once the episode has ended (the first call plans).
  bool step();
  // Steps until the episode ends; returns its metrics.
  const EpisodeMetrics& run();
  // A new task, taken in at the next step (docs/exec.md "A new task").
  // Thread-safe. Checked at once against the scenario as the tasks accepted
  // so far left it (task::with_task; its `time` is ignored): rtamp::Error
  // naming what is wrong — the refusal is also reported to observers (on_task)
  // at the next step — or if the episode has ended. `change.by` says who gave it.
  void set_task(world::TaskChange change);
  // Ends the episode at the next step (thread- and signal-safe).
  void stop(EndReason why = EndReason::Interrupted) { stop_.store(static_cast<int>(why)); }

  bool ended() const { return metrics_.end != EndReason::None; }
  const EpisodeMetrics& metrics() const { return metrics_; }
  // The observed run (symbolic states, in order) and, for recurring tasks, the
  // run index at which each counted cycle ended (cycle k is run[marks[k-1]..marks[k])).
  const std::vector<world::Placement>& observed_run() const { return run_; }
  const std::vector<std::size_t>& cycle_marks() const { return cycle_marks_; }
  const plan::TaskProgress& progress() const { return progress_; }
  // The run index at which the task in force took effect (0: the scenario's
  // task); the run is judged for it from there (cycle marks count from there).
  std::size_t task_from() const { return task_from_; }
  const PlanTree& tree() const { return *tree_; }
  const plan::Planner& planner() const { return *planner_; }
  const LoopOptions& options() const { return options_; }

 private:
  // Where a plan starts: a symbolic state, the hand, automaton states.
  struct Start {
    world::Placement placement;
    std::string hand;
    std::vector<std::uint32_t> states;
  };
  struct Starts {
    Start now;
    std::optional<Start> ahead;  // after the running move
    std::string cannot_finish;   // why the running move's place would be refused now ("" none)
  };
  // What the worker tells besides the plan (read after its future is ready).
  struct Outcome {
    std::vector<std::uint32_t> states;  // the automaton states the plan started from
    world::Placement placement;         // the state it started from (`now` or `ahead`)
    std::string hand;                   // and the hand's location ("" home)
    bool stop_running_move = false;     // planned from the current state: halt the running move
    std::string cannot_finish;          // Starts::cannot_finish: why it is halted
  };
  struct Pending {
    std::future<plan::PlanResult> future;
    std::optional<plan::PlanResult> result;
    double requested_at = 0;
    std::chrono::steady_clock::time_point wall_start;
    std::shared_ptr<Outcome> outcome;
  };

  void begin();
  void finish(EndReason why, std::string reason, bool success = false);
  std::string caused_by() const;
  void advance();
  void observe_world(world::Placement& symbolic, std::vector<std::string>& added, std::vector<std::string>& removed);
  void perceive();
  void rebuild_labeler();
  automata::Letter letter(const world::Placement& symbolic) const;
  void record_run_step(const world::Placement& next, bool things_changed, const std::vector<std::string>& added,
                       const std::vector<std::string>& removed);
  void apply_thing_changes(const std::vector<std::string>& added, const std::vector<std::string>& removed);
  void after_moves();
  static std::string state_key(const world::Placement& p);
  Starts starts();
  std::string place_refusal(const Move& m) const;
  void stop_running_move(const Outcome& outcome);
  void forbid_failed_moves(const Starts& st);
  void request_plan(const std::string& why);
  plan::PlanResult plan_from(const Starts& st, Outcome& out);
  bool collect_plan();
  void install(plan::PlanResult& r, bool first, const Outcome& outcome);
  void on_tree_done();
  // The run has closed a cycle since the last mark (cycle_satisfies): count
  // it, and once the episode's cycles are done stop starting moves. True if
  // a cycle was counted.
  bool count_cycle();
  bool settled() const;  // the percept has not changed for options_.settle, nor is a change being confirmed
  void finish_violated();  // ends: the run so far leaves the task no accepting future
  bool cycle_satisfies(std::size_t from) const;
  void wait_for_worker();
  // New tasks: the scheduled ones that are due and the inbox, in order.
  void take_task_changes();
  void apply_task_change(world::TaskChange c);
  // Whether the running move, finished, would leave the task no accepting future.
  bool running_move_defeats_task();

  World& world_;
  world::Scenario scenario_;  // with the things currently present
  LoopOptions options_;
  std::vector<EpisodeObserver*> observers_;
  std::unique_ptr<plan::Planner> planner_;
  std::unique_ptr<WorldRunner> runner_;
  std::unique_ptr<PlanTree> tree_;
  plan::TaskProgress progress_;
  // Labels of observed states, over the automaton's atoms (independent of the
  // planner, which a worker thread may be using).
  std::unique_ptr<task::System> label_ts_;
  std::unique_ptr<task::Labeling> labeling_;

  world::Placement seen_;      // last observation (held things in the hand), fed to the tree
  world::Placement symbolic_;  // current state of the run
  std::vector<world::Placement> run_;
  std::vector<automata::Letter> run_letters_;  // label of each state of the run, as it was entered
  std::vector<std::size_t> cycle_marks_;
  std::map<std::string, std::string> last_known_;  // each thing's last location (region or container)
  std::map<std::string, double> outside_since_;
  std::optional<Pending> pending_;
  Move last_move_;              // the last move that ran (its own effect is not a relocation)
  std::string running_before_;  // the tree's running action at the previous tick
  bool begun_ = false, recurring_ = false;
  bool disturbed_ = false;               // the world changed while the current move ran
  bool tree_done_ = false;               // the tree succeeded: the completion check is due
  double percept_changed_at_ = 0;        // world time the percept last changed not by the robot's moves
  bool replan_when_settled_ = false;     // no plan was found on an unsettled percept
  // The run's step that made the task impossible, on a percept not settled yet,
  // and the progress before it (undone if the percept comes back).
  struct Doubtful {
    std::size_t step;
    plan::TaskProgress progress;
  };
  std::optional<Doubtful> doubtful_;
  bool cycles_done_ = false;             // the last cycle is counted: the episode ends once the arm is free
  bool act_now_ = false;                 // tick again before time passes (a new tree, a due change)
  int same_time_steps_ = 0;
  static constexpr int kMaxSameTimeSteps = 100;
  int zero_steps_ = 0;
  int failures_seen_ = 0;
  // Undisturbed failures: state the move started from -> action -> how often.
  struct FailedMove {
    std::string thing, to;
    int count = 0;
  };
  std::map<std::string, std::map<std::string, FailedMove>> failed_moves_;
  std::string move_start_state_;              // state_key of the run when the running move began
  std::optional<WorldEvent> last_intervention_;  // the last applied one (named by an end it caused)
  std::vector<world::TaskChange> schedule_;  // options_.task_changes, in time order
  std::size_t next_task_change_ = 0;
  std::mutex inbox_mutex_;                   // guards the three below (set_task's thread)
  std::vector<world::TaskChange> task_inbox_;
  std::vector<std::pair<world::TaskChange, std::string>> task_refusals_;  // refused by set_task, to report
  world::Scenario task_vocabulary_;          // the scenario as the accepted tasks leave it
  bool inbox_closed_ = false;                // the episode has ended
  std::size_t task_from_ = 0;
  bool task_doubt_ = false;  // a new task judged impossible on a percept not settled yet
  std::atomic<double> now_{0};  // world time at the last step (set_task's thread reads it)
  std::atomic<int> stop_{0};
  EpisodeMetrics metrics_;
  std::chrono::steady_clock::time_point wall0_;
};

}  // namespace rtamp::exec
