// States of a synchronous product as pairs (x, y), numbered in the order of
// discovery; shared by product.cpp and suspended_product.cpp.
// Invariant: pair i of the worklist is state i of the output automaton.
#pragma once

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "rtamp/automata/automaton.hpp"

namespace rtamp::automata::detail {

class PairStates {
 public:
  explicit PairStates(Automaton& out) : out_(out) {}
  // The state of (x, y) in `out`, added (and queued) if new.
  std::uint32_t intern(std::uint32_t x, std::uint32_t y) {
    auto [it, fresh] = id_.emplace(std::make_pair(x, y), out_.num_states());
    if (fresh) {
      out_.add_state();
      todo_.emplace_back(x, y);
    }
    return it->second;
  }
  // Pairs discovered so far; grows while the caller adds edges.
  std::size_t size() const { return todo_.size(); }
  std::pair<std::uint32_t, std::uint32_t> operator[](std::size_t i) const { return todo_[i]; }

 private:
  Automaton& out_;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> id_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> todo_;
};

}  // namespace rtamp::automata::detail
