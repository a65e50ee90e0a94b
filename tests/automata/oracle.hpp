// Shared helpers of the translation tests: convert ltl::LassoWord (atom names)
// to automata::LassoWord (letters over an automaton's atoms).
#pragma once

#include "rtamp/automata/automaton.hpp"
#include "rtamp/automata/lasso_accept.hpp"
#include "rtamp/ltl/lasso.hpp"

namespace rtamp::automata::test {

inline Letter to_letter(const Automaton& a, const ltl::LassoWord::Letter& l) {
  Letter r = 0;
  for (const std::string& name : l)
    if (int i = a.find_atom(name); i >= 0) r |= Letter{1} << i;
  return r;
}

inline LassoWord to_word(const Automaton& a, const ltl::LassoWord& w) {
  LassoWord out;
  for (const auto& l : w.prefix) out.prefix.push_back(to_letter(a, l));
  for (const auto& l : w.cycle) out.cycle.push_back(to_letter(a, l));
  return out;
}

}  // namespace rtamp::automata::test
