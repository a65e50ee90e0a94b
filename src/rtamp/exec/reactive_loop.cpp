#include "rtamp/exec/reactive_loop.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/ltl/lasso.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/propositions.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::exec {

namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

std::optional<world::PropExpr> parse_atom(const std::string& atom) {
  try {
    return world::parse_prop_expr(atom);
  } catch (const Error&) {
    return std::nullopt;
  }
}

}  // namespace

const NameTable<PlanningMode>& planning_modes() {
  static const NameTable<PlanningMode> t = {
      {"worker", PlanningMode::Worker, "plan on a thread while the tree ticks, charging its time to world time"},
      {"inline", PlanningMode::Inline, "plan synchronously, charged nothing: deterministic"},
  };
  return t;
}

const LoopOptions& check_loop_options(const LoopOptions& o) {
  auto fail = [](const char* name, const std::string& rule, double v) {
    throw Error(std::string("loop option ") + name + ": " + rule + ", found " + format_number(v));
  };
  if (!(o.max_time > 0)) fail("max_time", "must be > 0 s (inf: no limit)", o.max_time);
  if (!(o.tick_period > 0 && std::isfinite(o.tick_period))) fail("tick_period", "must be finite and > 0 s", o.tick_period);
  if (!(o.outside_grace >= 0 && std::isfinite(o.outside_grace)))
    fail("outside_grace", "must be finite and >= 0 s", o.outside_grace);
  if (!(o.settle >= 0 && std::isfinite(o.settle))) fail("settle", "must be finite and >= 0 s", o.settle);
  if (o.max_failures_per_move < 1) fail("max_failures_per_move", "must be >= 1", o.max_failures_per_move);
  if (o.cycles < 0) fail("cycles", "must be >= 0 (0: no cycle count)", o.cycles);
  return o;
}

std::vector<world::TaskChange> check_task_schedule(const world::Scenario& s, std::vector<world::TaskChange> changes,
                                                  double max_time) {
  std::stable_sort(changes.begin(), changes.end(),
                   [](const world::TaskChange& a, const world::TaskChange& b) { return a.time < b.time; });
  task::validate_task_changes(s, changes);
  for (const world::TaskChange& c : changes)
    if (std::isfinite(max_time) && c.time >= max_time)
      throw Error("new task at t = " + format_number(c.time) + " s: the episode ends before it (max_time = " +
                      format_number(max_time) + " s of world time)",
                  c.where);
  return changes;
}

namespace {

bool cycle_has_moves(const plan::Plan& p) {
  return std::any_of(p.cycle.begin(), p.cycle.end(), [](const plan::Step& s) { return !s.action.is_stay(); });
}

// World time as the tree's clock (Timeout decorators see world time).
class WorldClock final : public bt::Clock {
 public:
  explicit WorldClock(const World& w) : world_(w) {}
  bt::Duration now() const override {
    return std::chrono::duration_cast<bt::Duration>(std::chrono::duration<double>(world_.time()));
  }

 private:
  const World& world_;
};

std::string seconds_text(double s) { return format_seconds(s); }

bool is_location(const world::Scenario& s, const world::Placement& p, const std::string& loc) {
  if (s.find_region(loc)) return true;
  auto it = p.things.find(loc);
  return it != p.things.end() && it->second.container;
}

}  // namespace

const char* to_string(EndReason r) {
  switch (r) {
    case EndReason::None: return "running";
    case EndReason::TaskDone: return "task-done";
    case EndReason::Cycles: return "cycles";
    case EndReason::Unsatisfiable: return "unsatisfiable";
    case EndReason::NoPlan: return "no-plan";
    case EndReason::GaveUp: return "gave-up";
    case EndReason::Lost: return "lost";
    case EndReason::TimeLimit: return "time-limit";
    case EndReason::Interrupted: return "interrupted";
    case EndReason::Error: return "error";
  }
  return "?";
}

ReactiveLoop::ReactiveLoop(World& world, const world::Scenario& scenario, LoopOptions options)
    : world_(world),
      scenario_(scenario),
      options_(check_loop_options(options)),
      planner_(std::make_unique<plan::Planner>(scenario_, options_.planner)),
      progress_(planner_->automaton()) {
  runner_ = std::make_unique<WorldRunner>(world_);
  runner_->on_event = [this](const char* what, const std::string& action, const std::string& why) {
    for (auto* o : observers_) o->on_action(world_.time(), what, action, why);
  };
  runner_->placed = [this](const Move& m) {
    const std::string* at = seen_.location_of(m.thing);
    return at && *at == m.to;
  };
  tree_ = std::make_unique<PlanTree>(options_.conditions, options_.reconfiguration, *runner_,
                                     std::make_shared<WorldClock>(world_));
  metrics_.seed = options_.seed;
  for (const auto& [name, thing] : world::initial_placement(scenario_).things) last_known_[name] = thing.location;
  // New tasks at world times: checked now, in order, each before the time limit.
  schedule_ = check_task_schedule(scenario_, options_.task_changes, options_.max_time);
  task_vocabulary_ = scenario_;
}

void ReactiveLoop::set_task(world::TaskChange change) {
  std::lock_guard<std::mutex> lock(inbox_mutex_);
  change.time = now_.load();
  if (inbox_closed_) throw Error("the episode has ended: a new task can no longer be given");
  try {
    task_vocabulary_ = task::with_task(task_vocabulary_, change);
  } catch (const Error& e) {
    task_refusals_.emplace_back(change, e.message());
    throw;
  }
  task_inbox_.push_back(std::move(change));
}

ReactiveLoop::~ReactiveLoop() {
  if (pending_ && !pending_->result) pending_->future.wait();
}

const EpisodeMetrics& ReactiveLoop::run() {
  while (step()) {
  }
  return metrics_;
}

// ---- labels and progress ------------------------------------------------------

void ReactiveLoop::rebuild_labeler() {
  labeling_.reset();
  label_ts_ = std::make_unique<task::System>(planner_->scenario(), symbolic_, std::string{});
  labeling_ = std::make_unique<task::Labeling>(*label_ts_, planner_->automaton().atoms, parse_atom);
}

automata::Letter ReactiveLoop::letter(const world::Placement& symbolic) const {
  return labeling_->label(label_ts_->encode(symbolic));
}

void ReactiveLoop::record_run_step(const world::Placement& next, bool things_changed,
                                   const std::vector<std::string>& added, const std::vector<std::string>& removed) {
  // The percept came back to what it was before a step that made the task
  // impossible, before it settled: that step was perception's, not the world's.
  if (doubtful_ && run_.size() >= 2 && next == run_[doubtful_->step - 1]) {
    symbolic_ = next;
    if (things_changed) apply_thing_changes(added, removed);
    run_.resize(doubtful_->step);
    run_letters_.resize(doubtful_->step);
    progress_ = doubtful_->progress;
    doubtful_.reset();
    for (auto* o : observers_) o->on_progress(world_.time(), symbolic_, progress_.states());
    return;
  }
  if (task_doubt_) {
    // A new task judged impossible on an unsettled percept: it is judged on
    // the percept as it settles, from the state it shows now.
    symbolic_ = next;
    if (things_changed) apply_thing_changes(added, removed);
    run_.push_back(symbolic_);
    run_letters_.push_back(letter(symbolic_));
    task_from_ = run_.size() - 1;
    progress_.reset();
    progress_.at(run_letters_.back());
    for (auto* o : observers_) o->on_progress(world_.time(), symbolic_, progress_.states());
    if (!progress_.dead() && progress_.can_still_accept()) {
      task_doubt_ = false;
      request_plan("the perceived placement changed after a new task");
    }
    return;
  }
  const plan::TaskProgress before = progress_;
  progress_.leave(run_letters_.back());  // the label of symbolic_, read as it entered the run
  symbolic_ = next;
  if (things_changed) apply_thing_changes(added, removed);
  run_.push_back(symbolic_);
  run_letters_.push_back(letter(symbolic_));
  progress_.at(run_letters_.back());
  for (auto* o : observers_) o->on_progress(world_.time(), symbolic_, progress_.states());
  if (progress_.dead() || !progress_.can_still_accept()) {
    if (!settled()) {  // judged once the percept has settled, unless it comes back first
      if (!doubtful_) doubtful_ = Doubtful{run_.size() - 1, before};
      return;
    }
    finish_violated();
    return;
  }
  // A cycle counts where the run closes it, whichever plans it took (a replan
  // after a failed move starts a new lasso, not a new round).
  count_cycle();
}

void ReactiveLoop::apply_thing_changes(const std::vector<std::string>& added,
                                       const std::vector<std::string>& removed) {
  constexpr auto kObserved = plan::Planner::ChangeOrigin::Observed;  // what the world showed, as it is
  wait_for_worker();
  pending_.reset();  // its plan is stale
  auto add = [&](bool containers) {
    for (const std::string& name : added) {
      const auto& thing = symbolic_.things.at(name);
      if (thing.container != containers) continue;
      if (thing.container) {
        int capacity = 4;
        for (const auto& k : planner_->scenario().containers)
          if (k.cls == thing.cls) capacity = k.capacity;
        planner_->apply(world::Change::add_container(name, thing.cls, thing.location, capacity), kObserved);
      } else {
        planner_->apply(world::Change::add_object(name, thing.cls, thing.location), kObserved);
      }
    }
  };
  for (const std::string& name : removed) {
    const bool container = planner_->placement().things.at(name).container;
    planner_->apply(container ? world::Change::remove_container(name) : world::Change::remove_object(name),
                    kObserved);
  }
  add(true);
  add(false);
  rebuild_labeler();
  for (auto* o : observers_) o->on_things_changed(world_.time(), added, removed);
}

// " (after the intervention at t = T: WHAT)" when a person's intervention
// changed the world since the last plan, " (the task given at t = T by WHO:
// TASK)" when the task in force is not the scenario's, both, or "".
std::string ReactiveLoop::caused_by() const {
  std::string out;
  if (metrics_.tasks.size() > 1) {
    const TaskOutcome& t = metrics_.tasks.back();
    out += " (the task given at t = " + seconds_text(t.time) + " by " + t.by + ": " + t.task + ")";
  }
  if (last_intervention_)
    out += " (after the intervention at t = " + seconds_text(last_intervention_->time) + ": " +
           last_intervention_->what.to_string() + ")";
  return out;
}

// ---- the episode ----------------------------------------------------------------

void ReactiveLoop::finish(EndReason why, std::string reason, bool success) {
  if (ended()) return;
  {
    std::lock_guard<std::mutex> lock(inbox_mutex_);
    inbox_closed_ = true;
  }
  if (!metrics_.tasks.empty()) {
    metrics_.tasks.back().outcome = to_string(why);
    metrics_.tasks.back().cycles = metrics_.cycles;
  }
  metrics_.end = why;
  metrics_.success = success;
  metrics_.reason = std::move(reason);
  if (success) metrics_.completion_time = world_.time();
  try {
    wait_for_worker();
  } catch (const std::exception&) {  // the episode ends for `why` already
  }
  pending_.reset();
  // A running tree is halted: a move still running stops (observers see it
  // before the end). A finished one keeps its statuses (the page shows them).
  try {
    if (tree_->tree().status() == bt::Status::Running) tree_->tree().halt();
  } catch (const std::exception&) {
  }
  metrics_.tree_changes = tree_->changes();
  metrics_.actions_succeeded = runner_->succeeded;
  metrics_.actions_failed = runner_->failed;
  metrics_.run_length = run_.size();
  metrics_.world_time = world_.time();
  metrics_.motion_cost = world_.distance_travelled();
  metrics_.wall_seconds = seconds_since(wall0_);
  metrics_.real_time_factor = metrics_.wall_seconds > 0 ? metrics_.world_time / metrics_.wall_seconds : 0;
  // The end's placement is what the world shows last (after the halt above).
  world::Placement last = seen_;
  try {
    if (begun_ && !seen_.things.empty()) last = world_.observe();
  } catch (const std::exception&) {
  }
  for (auto* o : observers_) o->on_end(world_.time(), metrics_, last);
}

// A planner exception on the worker (e.g. a cost model's bad value) is
// rethrown here with the worker forgotten: the episode ends with its error.
void ReactiveLoop::wait_for_worker() {
  if (!pending_ || pending_->result) return;
  try {
    pending_->result = pending_->future.get();
  } catch (...) {
    pending_.reset();
    throw;
  }
}

void ReactiveLoop::begin() {
  begun_ = true;
  wall0_ = Clock::now();
  if (const double t = world_.time(); !std::isfinite(t))
    throw Error("the world's time() returned " + format_number(t) + " at the start of the episode");
  EpisodeInfo info;
  info.scenario = scenario_.name;
  info.task = scenario_.task;
  info.algorithm = plan::to_string(options_.planner.algorithm);
  info.conditions = to_string(options_.conditions);
  info.reconfiguration = name_of(reconfigurations(), options_.reconfiguration);
  info.world = options_.world_name;
  info.seed = options_.seed;
  info.automaton = &planner_->automaton();
  for (auto* o : observers_) o->on_begin(info);
  metrics_.tasks.push_back(TaskOutcome{world_.time(), scenario_.task, "scenario", planner_->automaton().num_states()});

  // The first observation: things the world has beyond the scenario join the TS.
  world::Placement symbolic;
  std::vector<std::string> added, removed;
  observe_world(symbolic, added, removed);
  if (ended()) return;
  symbolic_ = symbolic;
  if (!added.empty() || !removed.empty()) apply_thing_changes(added, removed);
  else rebuild_labeler();
  run_.push_back(symbolic_);
  run_letters_.push_back(letter(symbolic_));
  progress_.reset();
  progress_.at(run_letters_.back());
  for (auto* o : observers_) o->on_progress(world_.time(), symbolic_, progress_.states());
  if (progress_.dead() || !progress_.can_still_accept()) {
    finish(EndReason::Unsatisfiable, "the task cannot be satisfied from the initial state");
    return;
  }
  now_.store(world_.time());

  // The first plan: the arm waits; its time is charged to world time — after
  // the plan is installed (its records carry the time planning began), so a
  // world paced from outside (a served episode started paused) has its first
  // plan before time first passes.
  const Starts st = starts();
  Outcome outcome;
  plan::PlanResult first;
  const bool worker = options_.planning == PlanningMode::Worker;
  if (worker) {
    // On a worker thread like every replan: the C library sets up a thread's
    // memory arena on its first allocation, and later workers reuse it, so
    // that cost lands here and not in the first replan.
    first = std::async(std::launch::async, [&] { return plan_from(st, outcome); }).get();
  } else {
    first = plan_from(st, outcome);
  }
  metrics_.first_plan_seconds = first.stats.seconds;
  if (!first.found) {
    if (worker) world_.advance(first.stats.seconds);
    finish(EndReason::NoPlan, std::string("no plan: ") + first.message);
    return;
  }
  install(first, true, outcome);
  if (worker) world_.advance(first.stats.seconds);
}

// Observes the world: the symbolic state of the run (held things at their
// source, things briefly outside every location at their last location) and
// the things that appeared or vanished. Feeds the tree's blackboard.
void ReactiveLoop::observe_world(world::Placement& symbolic, std::vector<std::string>& added,
                                 std::vector<std::string>& removed) {
  const double now = world_.time();
  world::Placement seen = world_.observe();
  for (const auto& [name, thing] : seen.things) {
    const std::string& at = thing.location;
    if (at == kInHand || at == world::kNoLocation || scenario_.find_region(at)) continue;
    auto c = seen.things.find(at);
    if (c == seen.things.end() || !c->second.container || at == name)
      throw Error("the world's observe() puts '" + name + "' in '" + at +
                  "', which is no region, present container, '" + kInHand + "' or '" + world::kNoLocation + "'");
  }
  if (seen != seen_) {
    for (auto* o : observers_) o->on_perceived(now, seen, seen_);
  }
  // A removed container's contents fall where it stood: so does the last known
  // location of a thing held out of it.
  for (auto& [name, loc] : last_known_) {
    if (seen.things.count(loc) || scenario_.find_region(loc)) continue;
    auto it = last_known_.find(loc);
    if (it != last_known_.end() && scenario_.find_region(it->second)) loc = it->second;
  }
  std::string lost;
  symbolic = seen;
  world::Placement for_tree = seen;
  for (auto it = symbolic.things.begin(); it != symbolic.things.end();) {
    auto& [name, thing] = *it;
    if (thing.location == "none") {
      const double since = outside_since_.emplace(name, now).first->second;
      if (now - since > options_.outside_grace) lost = name;
    } else {
      outside_since_.erase(name);
    }
    if (thing.location != kInHand && is_location(scenario_, seen, thing.location)) {
      last_known_[name] = thing.location;
    } else if (auto known = last_known_.find(name); known != last_known_.end()) {
      // Held: still at its source; outside: where it was. The tree sees it in
      // the hand or outside, so it starts no move of a thing that is not there.
      thing.location = known->second;
    } else {  // new, and in no location yet: ignored until it is
      for_tree.things.erase(name);
      it = symbolic.things.erase(it);
      continue;
    }
    if (!planner_->placement().things.count(name)) added.push_back(name);
    ++it;
  }
  for (const auto& [name, thing] : planner_->placement().things)
    if (!symbolic.things.count(name)) removed.push_back(name);
  // A thing that is gone is no longer outside anywhere.
  std::erase_if(outside_since_, [&](const auto& e) { return !seen.things.count(e.first); });
  seen_ = std::move(seen);
  tree_->placement() = std::move(for_tree);
  if (!lost.empty())
    finish(EndReason::Lost, "'" + lost + "' is outside every region and container (since t = " +
                                seconds_text(outside_since_.at(lost)) + "): nothing can plan with it");
}

void ReactiveLoop::perceive() {
  world::Placement next;
  std::vector<std::string> added, removed;
  observe_world(next, added, removed);
  if (ended()) return;
  const bool things_changed = !added.empty() || !removed.empty();
  // A relocation the robot's own running move does not explain.
  bool relocated = false;
  const Move& cur = runner_->current();
  for (const auto& [name, thing] : next.things) {
    auto before = symbolic_.things.find(name);
    if (before == symbolic_.things.end() || before->second.location == thing.location) continue;
    const bool own = name == cur.thing && thing.location == cur.to;
    const bool own_last = name == last_move_.thing && thing.location == last_move_.to;
    if (!own && !own_last) relocated = true;
  }
  if (relocated || things_changed) percept_changed_at_ = world_.time();  // not the robot's own doing
  if (!cur.action.empty() && (relocated || things_changed)) disturbed_ = true;
  if (things_changed || next != symbolic_) {
    record_run_step(next, things_changed, added, removed);
    if (ended()) return;
  }
  if (things_changed) {
    request_plan("things were added or removed");
  } else if (relocated) {
    if (const std::string by = tree_->handler(tree_->placement()); !by.empty()) {
      for (auto* o : observers_) o->on_handled_by_tree(world_.time(), by);
    } else {
      request_plan("a relocation no subtree can handle");
    }
  }
}

bool ReactiveLoop::step() {
  if (ended()) return false;
  try {
    if (!begun_) {
      begin();
      return !ended();
    }
    if (options_.interrupt && options_.interrupt->load() != 0) stop(EndReason::Interrupted);
    if (const int s = stop_.load(); s != 0) {
      const auto why = static_cast<EndReason>(s);
      finish(why, why == EndReason::Interrupted ? "interrupted" : to_string(why));
      return false;
    }
    if (world_.time() >= options_.max_time) {
      std::string reason = "time limit (" + seconds_text(options_.max_time) + " of world time)";
      if (recurring_)
        reason += options_.cycles > 0 ? " after " + std::to_string(metrics_.cycles) + " of " +
                                            std::to_string(options_.cycles) + " cycles"
                                      : " while repeating the plan's cycle: a recurring task never finishes "
                                        "(use --cycles K to stop after K cycles)";
      finish(EndReason::TimeLimit, reason);
      return false;
    }
    // Time passes only after the tree has been ticked on what is now: the
    // first step after a new plan or tree change ticks at the same moment.
    if (act_now_ && ++same_time_steps_ <= kMaxSameTimeSteps) {
      act_now_ = false;
    } else {
      act_now_ = false;
      same_time_steps_ = 0;
      advance();
    }
    for (const WorldEvent& e : world_.take_events()) {
      ++metrics_.interventions;
      ++(e.applied ? metrics_.interventions_applied : metrics_.interventions_refused);
      if (e.applied) last_intervention_ = e;
      for (auto* o : observers_) o->on_intervention(e);
    }
    perceive();
    if (ended()) return false;
    now_.store(world_.time());
    take_task_changes();
    if (ended()) return false;

    // Tick the tree (it waits while the arm makes itself safe after a halt).
    if (!world_.busy()) {
      if (auto r = tree_->retry_pending(); r && r->applied)
        for (auto* o : observers_) o->on_tree_change(world_.time(), *r, *tree_, true);
    }
    // While a replan is pending, no new step of the old plan starts: a running
    // move is still polled, an idle tree waits. A tree that has succeeded waits
    // for the completion check (once the arm is free), not for another pass.
    if ((doubtful_ || task_doubt_) && settled()) {
      finish_violated();
      return false;
    }
    if (replan_when_settled_ && !pending_ && settled()) {
      replan_when_settled_ = false;
      request_plan("the perceived placement has settled");
      if (ended()) return false;
    }
    tree_->hold(pending_.has_value() || cycles_done_ || replan_when_settled_ || doubtful_ || task_doubt_);
    if (cycles_done_ && runner_->current().action.empty() && !world_.busy() && settled()) {
      finish(EndReason::Cycles, "completed " + std::to_string(metrics_.cycles) + " cycles", true);
      return false;
    }
    const bool wait = world_.busy() || (pending_ && runner_->current().action.empty()) || tree_done_;
    const bt::Status status = wait ? bt::Status::Running : tree_->tick();
    if (!wait && status == bt::Status::Success) tree_done_ = true;
    const std::string running = tree_->running_action();
    for (auto* o : observers_) o->on_tick(world_.time(), status, running);
    if (!running.empty() && running != running_before_) {  // a new move began
      disturbed_ = false;
      move_start_state_ = state_key(symbolic_);
    }
    running_before_ = running;
    after_moves();
    if (ended()) return false;
    if (collect_plan()) return !ended();  // the status ticked above belongs to the old tree
    if (ended()) return false;
    if (tree_->has_pending() && running.empty() && !world_.busy()) act_now_ = true;  // a deferred change is due
    if (pending_ || tree_->has_pending()) return true;
    if (status == bt::Status::Failure) {
      // A thing outside every location is waited for (it comes back, or is lost
      // after outside_grace); otherwise the plan no longer fits what is seen.
      if (outside_since_.empty() && !replan_when_settled_) request_plan("no subtree can run in the perceived state");
    } else if (tree_done_ && runner_->current().action.empty() && !world_.busy()) {
      tree_done_ = false;
      on_tree_done();
    }
  } catch (const std::exception& e) {
    finish(EndReason::Error, std::string("error: ") + e.what());
  }
  return !ended();
}

// How far time moves in one step: a tick, or up to the next event of a
// discrete world — but never more than a tick while the arm is free and the
// tree has work (a discrete world must not skip a moment the robot could act).
void ReactiveLoop::advance() {
  const double now = world_.time();
  double dt = options_.tick_period;
  const double next_event = world_.next_event_time();
  if (std::isnan(next_event)) throw Error("the world's next_event_time() returned nan at t = " + seconds_text(now));
  if (std::isfinite(next_event)) {
    double next = std::min(next_event, options_.max_time);
    if (pending_) {
      wait_for_worker();
      next = std::min(next, pending_->requested_at + (options_.planning == PlanningMode::Worker
                                                          ? pending_->result->stats.seconds
                                                          : 0.0));
    }
    for (const auto& [name, since] : outside_since_) next = std::min(next, since + options_.outside_grace + 1e-6);
    if (next_task_change_ < schedule_.size()) next = std::min(next, std::max(now, schedule_[next_task_change_].time));
    // Waiting for the percept to settle, the tree is ticked as if the arm were free.
    const bool settling = (tree_done_ || replan_when_settled_ || doubtful_ || task_doubt_) && !settled();
    const bool arm_free = runner_->current().action.empty() && !world_.busy() && (!tree_done_ || settling);
    if (arm_free) next = std::min(next, now + options_.tick_period);
    dt = std::max(0.0, next - now);
    zero_steps_ = dt > 0 ? 0 : zero_steps_ + 1;
    if (zero_steps_ > 100) dt = options_.tick_period;  // a world that keeps announcing "now"
  } else if (pending_ && !pending_->result) {
    // The world runs faster than real time: while the worker plans, it may not
    // run further ahead of the request than the wall time the worker has had.
    const double ahead = (now + dt - pending_->requested_at) - seconds_since(pending_->wall_start);
    const auto wait = std::chrono::duration<double>(std::max(0.0, ahead));
    if (pending_->future.wait_for(wait) == std::future_status::ready) wait_for_worker();
  }
  if (dt > 0) world_.advance(dt);
  const double after = world_.time();
  if (!std::isfinite(after))
    throw Error("the world's time() returned " + format_number(after) + " after advance(" + format_number(dt) +
                ") at t = " + seconds_text(now));
  if (after < now)
    throw Error("the world's time() went back from " + format_number(now) + " to " + format_number(after) +
                " s after advance(" + format_number(dt) + ")");
}

// Failed moves: feedback to the planner, giving up.
void ReactiveLoop::after_moves() {
  if (runner_->failed > failures_seen_) {
    failures_seen_ = runner_->failed;
    // A move that failed with nobody disturbing it is remembered with the
    // state it started from: the planner avoids it from there while it can,
    // and too many failures of the same move from the same state end the
    // episode, whatever succeeded in between. One a person spoiled does neither.
    const Move& m = runner_->last_failed;
    if (const std::string* at = seen_.location_of(m.thing); !at || *at == world::kNoLocation) disturbed_ = true;
    if (!disturbed_) {
      FailedMove& f = failed_moves_[move_start_state_][m.action];
      f.thing = m.thing;
      f.to = m.to;
      const int n = ++f.count;
      if (n >= options_.max_failures_per_move) {
        finish(EndReason::GaveUp, "gave up: " + m.action + " failed " + std::to_string(n) +
                                      " times from the same state (max_failures_per_move = " +
                                      std::to_string(options_.max_failures_per_move) +
                                      "; last: " + runner_->last_failure + ")");
        return;
      }
    }
    disturbed_ = false;
  }
  if (!runner_->current().action.empty()) last_move_ = runner_->current();
}

// The key of a symbolic state for the failure memory: every thing's location.
std::string ReactiveLoop::state_key(const world::Placement& p) {
  std::string key;
  for (const auto& [name, thing] : p.things) key += name + '@' + thing.location + ' ';
  return key;
}

// The moves that failed from the states a plan starts from, forbidden to it
// (plan_from allows them again when no plan avoids them).
void ReactiveLoop::forbid_failed_moves(const Starts& st) {
  planner_->clear_forbidden_moves();
  for (const Start* s : {&st.now, st.ahead ? &*st.ahead : nullptr}) {
    if (!s) continue;
    auto it = failed_moves_.find(state_key(s->placement));
    if (it == failed_moves_.end()) continue;
    for (const auto& [action, f] : it->second)
      if (s->placement.things.count(f.thing) && is_location(scenario_, s->placement, f.to))
        planner_->forbid_move(f.thing, f.to);
  }
}

// ---- planning -----------------------------------------------------------------

// "" if the rule book of space lets the running move `m` put its thing at its
// destination in the current state (sizes and capacities as the planner has
// them, added things included), else why not.
std::string ReactiveLoop::place_refusal(const Move& m) const {
  const world::Scenario& in = planner_->scenario();
  const std::string why =
      world::refusal(m.thing, world::body_of(in, m.thing), m.to, world::location_now(in, symbolic_, m.to, m.thing));
  return why.empty() ? why : "cannot place " + m.thing + ": " + why;
}

// The planner's start: the current state, the hand and the tracked automaton
// states — and, while a move runs undisturbed, the state after that move
// (`ahead`, tried first: the move is not cut).
ReactiveLoop::Starts ReactiveLoop::starts() {
  Starts st;
  st.now.placement = symbolic_;
  st.now.hand = world_.hand();
  st.now.states = progress_.states();
  const Move& cur = runner_->current();
  if (!cur.action.empty() && !runner_->waiting()) {
    const std::string* at = seen_.location_of(cur.thing);
    const bool on_track = at && (*at == kInHand || *at == cur.from);
    if (on_track && symbolic_.things.count(cur.thing) && is_location(scenario_, symbolic_, cur.to) &&
        cur.to != cur.thing && (st.cannot_finish = place_refusal(cur)).empty()) {
      Start a = st.now;
      a.placement.things.at(cur.thing).location = cur.to;
      a.hand = cur.to;
      if (a.placement != symbolic_) {
        plan::TaskProgress ahead = progress_;
        ahead.leave(letter(symbolic_));
        ahead.at(letter(a.placement));
        a.states = ahead.states();
      }
      st.ahead = std::move(a);
    }
  }
  for (Start* s : {&st.now, st.ahead ? &*st.ahead : nullptr})
    if (s && !is_location(scenario_, s->placement, s->hand)) s->hand.clear();  // home, or a container gone
  return st;
}

void ReactiveLoop::request_plan(const std::string& why) {
  if (pending_ || ended()) return;
  Starts st = starts();
  forbid_failed_moves(st);
  for (auto* o : observers_) o->on_replan_request(world_.time(), why);
  Pending p;
  p.requested_at = world_.time();
  p.wall_start = Clock::now();
  p.outcome = std::make_shared<Outcome>();
  if (options_.planning == PlanningMode::Worker) {
    p.future = std::async(std::launch::async,
                          [this, st = std::move(st), out = p.outcome] { return plan_from(st, *out); });
    pending_ = std::move(p);
  } else {
    p.result = plan_from(st, *p.outcome);
    pending_ = std::move(p);
    collect_plan();  // synchronous: in use at once
  }
}

// A plan from the state after the running move, else from the current state
// (the running move then has to stop: it leads nowhere); if forbidden moves
// (failed earlier) leave no plan, they are allowed again. Runs on the worker.
plan::PlanResult ReactiveLoop::plan_from(const Starts& st, Outcome& out) {
  double seconds = 0;
  auto attempt = [&](const Start& s) {
    planner_->set_placement(s.placement, s.hand);
    planner_->set_automaton_states(s.states);
    out.states = s.states;
    out.placement = s.placement;
    out.hand = s.hand;
    plan::PlanResult r = planner_->plan();
    if (!r.found && !planner_->forbidden_moves().empty()) {
      seconds += r.stats.seconds;
      planner_->clear_forbidden_moves();
      r = planner_->plan();
    }
    seconds += r.stats.seconds;
    return r;
  };
  plan::PlanResult r = st.ahead ? attempt(*st.ahead) : attempt(st.now);
  if (!st.cannot_finish.empty()) {  // the running move cannot finish: it stops, its thing put back
    out.stop_running_move = true;
    out.cannot_finish = st.cannot_finish;
  }
  if (!r.found && st.ahead) {
    plan::PlanResult now = attempt(st.now);
    if (now.found) {
      out.stop_running_move = true;
      r = std::move(now);
    }
  }
  r.stats.seconds = seconds;
  return r;
}

// Installs a finished replan once its planning time has passed in world time.
bool ReactiveLoop::collect_plan() {
  if (!pending_ || !pending_->result) return false;
  const double charged = options_.planning == PlanningMode::Worker ? pending_->result->stats.seconds : 0.0;
  if (world_.time() < pending_->requested_at + charged) return false;
  plan::PlanResult r = std::move(*pending_->result);
  const Outcome outcome = *pending_->outcome;
  pending_.reset();
  ++metrics_.replans;
  metrics_.replan_seconds += r.stats.seconds;
  if (!r.found) {
    if (!settled()) {  // not judged on a percept that may still be catching up: asked again once settled
      replan_when_settled_ = true;
      if (outcome.stop_running_move) stop_running_move(outcome);
      return true;
    }
    finish(r.reason == plan::NoPlanReason::NoAcceptingCycle ? EndReason::Unsatisfiable : EndReason::NoPlan,
           std::string("no plan: ") + r.message + caused_by());
    return true;
  }
  if (outcome.stop_running_move) stop_running_move(outcome);
  install(r, false, outcome);
  return true;
}

// Halts the running move (the world puts its thing back); a move the rule book
// stopped is reported as a redirection with the reason.
void ReactiveLoop::stop_running_move(const Outcome& outcome) {
  const std::string action = runner_->current().action;
  tree_->tree().halt();
  if (!outcome.cannot_finish.empty() && !action.empty())
    for (auto* o : observers_)
      o->on_redirect(world_.time(), action,
                     outcome.cannot_finish + " — the move cannot finish: halted, its thing put back where it was "
                                             "picked (or another valid place), planned from there");
}

void ReactiveLoop::install(plan::PlanResult& r, bool first, const Outcome& outcome) {
  recurring_ = cycle_has_moves(r.plan);
  tree_done_ = false;
  replan_when_settled_ = false;
  act_now_ = true;  // the new tree ticks before time passes
  last_intervention_.reset();  // the plan has taken it in
  const std::vector<plan::ActionTuple> tuples = planner_->action_tuples(r.plan);
  const PlanEvent ev{first, r, tuples, outcome.states, outcome.placement, outcome.hand};
  for (auto* o : observers_) o->on_plan(world_.time(), ev);
  const ReconfigurationReport rep = tree_->set_plan(tuples);
  for (auto* o : observers_) o->on_tree_change(world_.time(), rep, *tree_, false);
}

// Every step of the tree is done: finished, a cycle completed, or replan.
void ReactiveLoop::on_tree_done() {
  // A thing outside every location is somewhere unknown: wait until it is
  // seen again (a new step of the run) or is lost, before judging the task.
  if (!outside_since_.empty()) {
    tree_done_ = true;
    return;
  }
  if (progress_.satisfied_by_staying(run_letters_.back())) {
    if (!settled()) {  // judged again at the next step, on what is perceived then
      tree_done_ = true;
      return;
    }
    finish(EndReason::TaskDone, "task done", true);
    return;
  }
  if (recurring_ && (count_cycle() || (!cycle_marks_.empty() && cycle_marks_.back() == run_.size() - 1))) {
    if (!cycles_done_) request_plan("cycle " + std::to_string(metrics_.cycles) + " completed: next round");
    return;
  }
  request_plan("every step is done but the task is not");
}

void ReactiveLoop::finish_violated() {
  finish(EndReason::Unsatisfiable,
         "the task can no longer be satisfied: no run of its automaton is consistent with what happened "
         "and can still be accepted" + caused_by());
}

// ---- new tasks ------------------------------------------------------------------

void ReactiveLoop::take_task_changes() {
  std::vector<world::TaskChange> due;
  std::vector<std::pair<world::TaskChange, std::string>> refused;
  {
    std::lock_guard<std::mutex> lock(inbox_mutex_);
    refused.swap(task_refusals_);
    due.swap(task_inbox_);
  }
  const double now = world_.time();
  for (const auto& [c, why] : refused)
    for (auto* o : observers_) o->on_task(now, TaskEvent{c, false, why, nullptr});
  std::vector<world::TaskChange> scheduled;
  while (next_task_change_ < schedule_.size() && schedule_[next_task_change_].time <= now + 1e-9)
    scheduled.push_back(schedule_[next_task_change_++]);
  due.insert(due.begin(), scheduled.begin(), scheduled.end());
  for (world::TaskChange& c : due) {
    apply_task_change(std::move(c));
    if (ended()) return;
  }
}

bool ReactiveLoop::running_move_defeats_task() {
  const Starts st = starts();
  if (!st.ahead) return false;
  plan::TaskProgress p = progress_;
  p.leave(letter(symbolic_));
  p.at(letter(st.ahead->placement));
  return p.dead() || !p.can_still_accept();
}

void ReactiveLoop::apply_task_change(world::TaskChange c) {
  const double now = world_.time();
  c.time = now;
  wait_for_worker();  // the worker uses the planner
  try {
    planner_->set_task(c);  // checks first (e.g. a proposition another task change redefined): nothing changes on a refusal
  } catch (const Error& e) {
    for (auto* o : observers_) o->on_task(now, TaskEvent{c, false, e.message(), nullptr});
    return;
  }
  pending_.reset();  // a plan for the old task
  scenario_.task = planner_->scenario().task;
  scenario_.propositions = planner_->scenario().propositions;
  TaskOutcome& before = metrics_.tasks.back();
  before.outcome = "superseded";
  before.cycles = metrics_.cycles;
  metrics_.tasks.push_back(TaskOutcome{now, c.task, c.by, planner_->automaton().num_states()});

  // Progress restarts at the new automaton's initial state on the current state.
  rebuild_labeler();
  progress_ = plan::TaskProgress(planner_->automaton());
  progress_.reset();
  run_letters_.back() = letter(symbolic_);
  progress_.at(run_letters_.back());
  task_from_ = run_.size() - 1;
  cycle_marks_.clear();
  metrics_.cycles = 0;
  cycles_done_ = recurring_ = false;
  doubtful_.reset();
  task_doubt_ = replan_when_settled_ = tree_done_ = false;
  for (auto* o : observers_) o->on_task(now, TaskEvent{c, true, {}, &planner_->automaton()});
  for (auto* o : observers_) o->on_progress(now, symbolic_, progress_.states());

  const std::string given = "the new task given at t = " + seconds_text(now) + " by " + c.by + " (" + c.task + ")";
  if (progress_.dead() || !progress_.can_still_accept()) {
    if (settled()) {
      finish(EndReason::Unsatisfiable, given + " cannot be satisfied from the current state");
      return;
    }
    task_doubt_ = true;  // judged once the percept has settled (record_run_step, step)
    return;
  }
  if (progress_.satisfied_by_staying(run_letters_.back()) && settled() && outside_since_.empty()) {
    if (runner_->current().action.empty() && !world_.busy()) {
      finish(EndReason::TaskDone, "task done: the current state satisfies " + given, true);
      return;
    }
    // The arm holds a thing: it is put back (where it was picked, in the
    // state that satisfies the task), and the task is judged once it is down.
    if (const std::string action = runner_->current().action; !action.empty()) {
      tree_->tree().halt();
      for (auto* o : observers_)
        o->on_redirect(now, action, "the current state satisfies the new task: halted, its thing put back where it "
                                    "was picked, then the task is judged");
    }
    tree_done_ = true;
    return;
  }
  if (running_move_defeats_task()) {
    const std::string action = runner_->current().action;
    tree_->tree().halt();  // the world puts its thing back (at its source, or another valid place)
    for (auto* o : observers_)
      o->on_redirect(now, action,
                     "finishing it would leave the new task no accepting future: halted, its thing put back "
                     "where the new task allows (where it was picked, or another valid place)");
  }
  request_plan("a new task was given: " + c.task);
}

bool ReactiveLoop::settled() const {
  return world_.time() - percept_changed_at_ >= options_.settle - 1e-9 && !world_.confirming();
}

bool ReactiveLoop::count_cycle() {
  if (!recurring_ || cycles_done_) return false;
  const std::size_t from = cycle_marks_.empty() ? task_from_ : cycle_marks_.back();
  if (!cycle_satisfies(from)) return false;
  ++metrics_.cycles;
  cycle_marks_.push_back(run_.size() - 1);
  for (auto* o : observers_) o->on_cycle(world_.time(), metrics_.cycles);
  cycles_done_ = options_.cycles > 0 && metrics_.cycles >= options_.cycles;
  return true;
}

// Some earlier visit j >= from of the current state closes a cycle
// run[j..end) such that run[task_from..j) · run[j..end)^ω satisfies the task
// in force (the direct LTL semantics; the run before the task took effect
// does not count).
bool ReactiveLoop::cycle_satisfies(std::size_t from) const {
  if (!planner_->formula() || run_.size() < task_from_ + 2) return false;
  const std::size_t end = run_.size() - 1;
  const auto& atoms = planner_->automaton().atoms;
  auto word_of = [&](automata::Letter l) {
    ltl::LassoWord::Letter w;
    for (std::size_t i = 0; i < atoms.size(); ++i)
      if (l >> i & 1u) w.insert(atoms[i]);
    return w;
  };
  for (std::size_t j = end; j-- > from;) {
    if (run_[j] != run_[end]) continue;
    ltl::LassoWord w;
    for (std::size_t i = task_from_; i < j; ++i) w.prefix.push_back(word_of(run_letters_[i]));
    for (std::size_t i = j; i < end; ++i) w.cycle.push_back(word_of(run_letters_[i]));
    if (ltl::holds(planner_->formula(), w)) return true;
  }
  return false;
}

}  // namespace rtamp::exec
