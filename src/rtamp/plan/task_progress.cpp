#include "rtamp/plan/task_progress.hpp"

#include <algorithm>

namespace rtamp::plan {

namespace {

// Per state: it can reach (by the kept edges, zero or more steps) a strongly
// connected component that has an internal edge and whose internal edges
// carry every acceptance set (state-based automata: the marks of an edge are
// its source's; num_sets == 0: any cycle). `letter` null: every edge whose
// guard is satisfiable; else only edges whose guard matches *letter.
std::vector<bool> reaches_accepting_cycle(const automata::Automaton& ba, const automata::Letter* letter) {
  const std::uint32_t n = ba.num_states();
  auto kept = [&](const automata::Edge& e) { return letter ? e.guard.matches(*letter) : !e.guard.is_false(); };
  // reach[p][q]: q reachable from p in >= 1 kept edge. Automata are small.
  std::vector<std::vector<bool>> reach(n, std::vector<bool>(n, false));
  for (std::uint32_t p = 0; p < n; ++p) {
    std::vector<std::uint32_t> stack;
    for (const auto& e : ba.edges[p])
      if (kept(e) && !reach[p][e.dst]) {
        reach[p][e.dst] = true;
        stack.push_back(e.dst);
      }
    while (!stack.empty()) {
      const std::uint32_t q = stack.back();
      stack.pop_back();
      for (const auto& e : ba.edges[q])
        if (kept(e) && !reach[p][e.dst]) {
          reach[p][e.dst] = true;
          stack.push_back(e.dst);
        }
    }
  }
  const automata::Marks all = ba.all_marks();
  std::vector<bool> good(n, false);  // q lies in an accepting SCC
  for (std::uint32_t q = 0; q < n; ++q) {
    if (!reach[q][q]) continue;  // no cycle through q
    automata::Marks m = 0;
    for (std::uint32_t p = 0; p < n; ++p) {
      if (!(p == q || (reach[q][p] && reach[p][q]))) continue;
      for (const auto& e : ba.edges[p]) {
        if (!kept(e) || !(e.dst == q || (reach[q][e.dst] && reach[e.dst][q]))) continue;
        m |= ba.state_based ? (ba.state_accepting[p] ? automata::Marks{1} : 0) : e.marks;
      }
    }
    good[q] = ba.num_sets == 0 || (m & all) == all;
  }
  std::vector<bool> out(n, false);
  for (std::uint32_t p = 0; p < n; ++p) {
    out[p] = good[p];
    for (std::uint32_t q = 0; q < n && !out[p]; ++q) out[p] = reach[p][q] && good[q];
  }
  return out;
}

}  // namespace

TaskProgress::TaskProgress(const automata::Automaton& ba) : ba_(&ba) {
  useful_ = reaches_accepting_cycle(ba, nullptr);
  reset();
}

void TaskProgress::reset() {
  at_ = false;
  states_.clear();
  if (ba_->num_states() > 0) states_.push_back(ba_->initial);
}

std::vector<std::uint32_t> TaskProgress::closure(const std::vector<std::uint32_t>& from, automata::Letter l) const {
  std::vector<bool> seen(ba_->num_states(), false);
  std::vector<std::uint32_t> out, stack;
  for (const std::uint32_t q : from)
    if (!seen[q]) {
      seen[q] = true;
      stack.push_back(q);
    }
  while (!stack.empty()) {
    const std::uint32_t q = stack.back();
    stack.pop_back();
    out.push_back(q);
    for (const auto& e : ba_->edges[q])
      if (e.guard.matches(l) && !seen[e.dst]) {
        seen[e.dst] = true;
        stack.push_back(e.dst);
      }
  }
  std::sort(out.begin(), out.end());
  return out;
}

void TaskProgress::at(automata::Letter here) {
  states_ = closure(states_, here);
  at_ = true;
  here_ = here;
}

void TaskProgress::leave(automata::Letter here) {
  const std::vector<std::uint32_t> cur = closure(states_, here);
  std::vector<bool> next(ba_->num_states(), false);
  for (const std::uint32_t q : cur)
    for (const auto& e : ba_->edges[q])
      if (e.guard.matches(here)) next[e.dst] = true;
  states_.clear();
  at_ = false;
  for (std::uint32_t q = 0; q < ba_->num_states(); ++q)
    if (next[q]) states_.push_back(q);
}

bool TaskProgress::satisfied_by_staying(automata::Letter here) const {
  if (states_.empty()) return false;
  const std::vector<bool> ok = reaches_accepting_cycle(*ba_, &here);
  return std::any_of(states_.begin(), states_.end(), [&](std::uint32_t q) { return ok[q]; });
}

bool TaskProgress::can_still_accept() const {
  return std::any_of(states_.begin(), states_.end(), [&](std::uint32_t q) {
    if (!at_) return static_cast<bool>(useful_[q]);
    return std::any_of(ba_->edges[q].begin(), ba_->edges[q].end(),
                       [&](const automata::Edge& e) { return e.guard.matches(here_) && useful_[e.dst]; });
  });
}

}  // namespace rtamp::plan
