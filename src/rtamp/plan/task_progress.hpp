// Progress along the executed run (paper Algorithm 1, lines 9-12: the
// planner needs to know where the task stands when it replans; see
// docs/planning.md "Progress along the executed run").
//
// TaskProgress tracks the set Q of Büchi-automaton states consistent with
// the run that actually happened. The run is the sequence of observed
// symbolic states s0 s1 ... sk (the robot at sk now). The automaton reads
// the label of a state when the run leaves it, as the product's edges do:
// (s, q) -> (s', q') with q' in δ(q, L(s)). The robot may stay in a state any
// number of steps (the TS's stay action reads L(s) once per step), so the run
// is known only up to stuttering: at sk the automaton may have read L(sk) any
// number of times n >= 0 already, and Q = δ*(δ(...δ(Q0, L(s0)^+)..., L(s_{k-1})^+),
// L(sk)^*) with Q0 = {initial}.
//   at(L(sk))     closes Q under reading L(sk) (zero or more times);
//   leave(L(sk))  the run leaves sk: Q := δ(closure(Q), L(sk)).
// Typical use: reset(); at(L(s0)); then per observed change leave(L(old));
// at(L(new)).
// Invariants: states() is sorted and duplicate-free; after at(l), Q is closed
// under δ(·, l); dead() iff Q is empty (the observed history alone makes the
// task unsatisfiable). Works for state-based Büchi automata and for
// transition-based generalized ones (acceptance from edge marks).
// The automaton must outlive the tracker (it is referenced, so trackers copy
// cheaply: the executor copies one to look ahead).
#pragma once

#include <cstdint>
#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::plan {

class TaskProgress {
 public:
  explicit TaskProgress(const automata::Automaton& ba);

  // Q := {initial}; no closure until at() is called.
  void reset();
  // The run is at a state labelled `here`: close Q under reading `here`.
  void at(automata::Letter here);
  // The run leaves a state labelled `here`: Q := δ(closure_here(Q), here).
  void leave(automata::Letter here);

  const std::vector<std::uint32_t>& states() const { return states_; }
  bool dead() const { return states_.empty(); }
  // Staying forever in a state labelled `here` is accepted from some tracked
  // state: an accepting cycle of edges whose guards hold for `here` is
  // reachable from Q by such edges.
  bool satisfied_by_staying(automata::Letter here) const;
  // Some tracked state can still reach an accepting cycle (by any letters).
  // After at(l) the current state's label l is still to be read at least once
  // (leaving it or staying forever reads it), so then only states with an
  // l-edge into such a state count: e.g. for G a the task is hopeless as soon
  // as the run is at a state without a, though Q is not empty.
  bool can_still_accept() const;
  // q can reach an accepting cycle (by any letters).
  bool useful(std::uint32_t q) const { return useful_[q]; }
  const automata::Automaton& automaton() const { return *ba_; }

 private:
  // States reachable from `from` by edges whose guard matches `l` (zero or more steps).
  std::vector<std::uint32_t> closure(const std::vector<std::uint32_t>& from, automata::Letter l) const;

  const automata::Automaton* ba_;
  std::vector<std::uint32_t> states_;
  bool at_ = false;              // at() was called since the last reset() / leave()
  automata::Letter here_ = 0;    // its letter
  std::vector<bool> useful_;
};

}  // namespace rtamp::plan
