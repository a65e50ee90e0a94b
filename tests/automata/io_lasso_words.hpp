// Test support for the automata I/O tests (HOA, never claims, spin oracle):
// lasso words over atom *names* (ltl::LassoWord), projected onto an
// automaton's own atom order, so that automata with different atom orders
// (ours, spin's, a re-read HOA file) can be run on the same words.
#pragma once

#include <random>
#include <string>
#include <vector>

#include "rtamp/automata/automaton.hpp"
#include "rtamp/automata/lasso_accept.hpp"
#include "rtamp/ltl/lasso.hpp"

namespace rtamp::automata::testing {

// The word over the automaton's atoms (names the automaton lacks are dropped).
inline LassoWord project(const ltl::LassoWord& w, const std::vector<std::string>& atoms) {
  auto letter = [&](const ltl::LassoWord::Letter& l) {
    Letter x = 0;
    for (std::size_t i = 0; i < atoms.size(); ++i)
      if (l.count(atoms[i])) x |= Letter{1} << i;
    return x;
  };
  LassoWord out;
  for (const auto& l : w.prefix) out.prefix.push_back(letter(l));
  for (const auto& l : w.cycle) out.cycle.push_back(letter(l));
  return out;
}

inline bool accepts(const Automaton& a, const ltl::LassoWord& w) { return lasso_accept(a, project(w, a.atoms)); }

// Every lasso over `atoms` with prefix length <= max_prefix and cycle length
// in [1, max_cycle].
inline std::vector<ltl::LassoWord> all_lassos(const std::vector<std::string>& atoms, std::size_t max_prefix,
                                              std::size_t max_cycle) {
  const std::size_t nl = std::size_t{1} << atoms.size();
  auto letter = [&](std::size_t v) {
    ltl::LassoWord::Letter l;
    for (std::size_t i = 0; i < atoms.size(); ++i)
      if (v >> i & 1) l.insert(atoms[i]);
    return l;
  };
  auto sequences = [&](std::size_t len) {
    std::vector<std::vector<ltl::LassoWord::Letter>> out;
    std::size_t total = 1;
    for (std::size_t i = 0; i < len; ++i) total *= nl;
    for (std::size_t code = 0; code < total; ++code) {
      std::vector<ltl::LassoWord::Letter> s;
      std::size_t c = code;
      for (std::size_t i = 0; i < len; ++i, c /= nl) s.push_back(letter(c % nl));
      out.push_back(std::move(s));
    }
    return out;
  };
  std::vector<ltl::LassoWord> words;
  for (std::size_t p = 0; p <= max_prefix; ++p)
    for (auto& pre : sequences(p))
      for (std::size_t c = 1; c <= max_cycle; ++c)
        for (auto& cyc : sequences(c)) words.push_back({pre, cyc});
  return words;
}

}  // namespace rtamp::automata::testing
