#include "rtamp/automata/split.hpp"

#include "rtamp/ltl/syntactic_class.hpp"

namespace rtamp::automata::detail {

using ltl::Formula;
using ltl::Op;

std::optional<Split> split_formula(const Formula& nnf) {
  if (!nnf.is(Op::And) && !nnf.is(Op::Or)) return std::nullopt;
  if (ltl::is_syntactic_obligation(nnf)) return std::nullopt;
  std::vector<Formula> obligations, suspendable, rest, safety;
  for (const Formula& c : nnf.children()) {
    if (ltl::is_syntactic_obligation(c))
      (ltl::is_syntactic_safety(c) ? safety : obligations).push_back(c);
    else if (c.is_eventual() && c.is_universal())
      suspendable.push_back(c);
    else
      rest.push_back(c);
  }
  if (rest.empty())
    obligations.insert(obligations.end(), safety.begin(), safety.end());
  else
    rest.insert(rest.end(), safety.begin(), safety.end());
  Split s;
  s.op = nnf.op();
  if (!obligations.empty()) s.parts.push_back(Formula::nary(s.op, obligations));
  if (!rest.empty()) s.parts.push_back(Formula::nary(s.op, rest));
  s.suspendable = std::move(suspendable);
  if (s.parts.size() + s.suspendable.size() < 2) return std::nullopt;
  return s;
}

}  // namespace rtamp::automata::detail
