#include "rtamp/exec/timeline.hpp"

#include <cstdio>

#include "rtamp/bt/text_render.hpp"
#include "rtamp/util/format.hpp"

namespace rtamp::exec {

namespace {

// 145 us, 1.2 ms, 3.4 s: the CLI's one formatter (util/format.hpp).
std::string duration(double s) { return format_seconds(s); }

std::string thing_of(const std::string& action) {  // "move(o1, r2)" -> "o1"
  const auto open = action.find('('), comma = action.find(',');
  return open == std::string::npos || comma == std::string::npos ? std::string{}
                                                                   : action.substr(open + 1, comma - open - 1);
}

std::string subtrees(const PlanTree& tree) {
  std::string lines;
  for (const bt::Node* c : tree.tree().root()->children())
    lines += "\n    " + std::string(bt::to_string(c->status())) + "  " + c->name();
  return lines.empty() ? std::string(" (empty)") : lines;
}

}  // namespace

void Timeline::say(double t, const std::string& line) {
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "[%7.2f s] ", t);
  sink_(stamp + line);
}

void Timeline::on_action(double t, const char* what, const std::string& action, const std::string& why) {
  if (std::string(what) == "start") moving_ = thing_of(action);
  say(t, std::string(what) + " " + action + (why.empty() ? "" : " (" + why + ")"));
}

void Timeline::on_intervention(const WorldEvent& e) {
  say(e.time, "operator: " + std::string(to_string(e.what.kind)) + " " + e.what.subject +
                  (e.what.location.empty() ? "" : " -> " + e.what.location) +
                  (e.applied ? (e.detail.empty() ? "" : " (" + e.detail + ")") : " (refused: " + e.detail + ")"));
}

void Timeline::on_perceived(double t, const world::Placement& seen, const world::Placement& before) {
  for (const auto& [name, thing] : seen.things) {
    const std::string* was = before.location_of(name);
    if (!was || *was == thing.location || name == moving_ || thing.location == kInHand || *was == kInHand) continue;
    say(t, "perceived " + name + " in " + thing.location + " (was in " + *was + ")");
  }
  last_seen_ = seen;
}

void Timeline::on_things_changed(double t, const std::vector<std::string>& added,
                                 const std::vector<std::string>& removed) {
  for (const auto& name : added) {
    const auto it = last_seen_.things.find(name);
    say(t, "perceived new " + (it == last_seen_.things.end() ? std::string("thing") : it->second.cls) + " " + name +
               (it == last_seen_.things.end() ? "" : " in " + it->second.location));
  }
  for (const auto& name : removed) say(t, "perceived " + name + " is gone");
}

void Timeline::on_progress(double t, const world::Placement&, const std::vector<std::uint32_t>& states) {
  if (states == last_states_) return;
  last_states_ = states;
  std::string list;
  for (auto q : states) list += (list.empty() ? "" : ", ") + std::to_string(q);
  say(t, "task progress: automaton in {" + list + "}");
}

void Timeline::on_handled_by_tree(double t, const std::string& by) {
  say(t, "the tree can go on (" + (by == "every step is done" ? by : "can run " + by) + "): no replanning");
}

void Timeline::on_replan_request(double t, const std::string& why) { say(t, "replanning: " + why); }

void Timeline::on_plan(double t, const PlanEvent& e) {
  std::size_t moves = e.tuples.size();
  const auto& s = e.result.stats;
  std::string head = std::string(e.first ? "first plan in " : "replanned in ") + duration(s.seconds) + ": " +
                     std::to_string(moves) + (moves == 1 ? " move" : " moves") + ", cost " +
                     format_number(e.result.plan.cost(), 4);
  if (s.cache_used)
    head += " (cache hits " + std::to_string(s.cache_hits) + ", misses " + std::to_string(s.cache_misses) + ")";
  say(t, head);
  std::string listed;
  for (const auto& tu : e.tuples) listed += (listed.empty() ? "" : ", ") + tu.action + (tu.in_cycle ? "*" : "");
  say(t, "plan: " + (listed.empty() ? std::string("nothing to move") : listed) +
             (listed.find('*') != std::string::npos ? "  (* repeats: the plan's cycle)" : ""));
}

void Timeline::on_tree_change(double t, const ReconfigurationReport& r, const PlanTree& tree, bool deferred) {
  if (!r.applied) {
    say(t, "tree change deferred: a running move must finish first");
    return;
  }
  if (first_tree_) {
    first_tree_ = false;
    say(t, "tree:\n" + bt::to_text(tree.tree()));
    return;
  }
  say(t, std::string(deferred ? "deferred tree change applied" : "tree") + ": +" + std::to_string(r.inserted) + " -" +
             std::to_string(r.removed) + " subtrees, " + std::to_string(r.updated) + " updated (" +
             std::to_string(tree.changes()) + " changes so far)");
  if (r.inserted + r.removed > 0) say(t, "tree now:" + subtrees(tree));
}

void Timeline::on_cycle(double t, int completed) { say(t, "cycle " + std::to_string(completed) + " completed"); }

void Timeline::on_task(double t, const TaskEvent& e) {
  if (!e.applied) {
    say(t, "new task from " + e.change.by + " refused: " + e.refused);
    return;
  }
  const std::size_t n = e.automaton ? e.automaton->num_states() : 0;
  say(t, "new task from " + e.change.by + ": " + e.change.task + " (" + std::to_string(n) +
             (n == 1 ? " automaton state)" : " automaton states)"));
}

void Timeline::on_redirect(double t, const std::string& action, const std::string& rule) {
  say(t, "redirected " + action + ": " + rule);
}

void Timeline::on_tick(double, bt::Status, const std::string& running) {
  if (running.empty()) moving_.clear();
}

void Timeline::on_end(double t, const EpisodeMetrics& m, const world::Placement&) {
  say(t, m.success ? (m.end == EndReason::Cycles ? m.reason : std::string("task done")) : "episode ended: " + m.reason);
}

}  // namespace rtamp::exec
