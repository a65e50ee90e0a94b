#include "rtamp/ltl/syntactic_class.hpp"

namespace rtamp::ltl {

namespace {

template <class Pred>
bool all_children(const Formula& f, Pred&& pred) {
  for (const Formula& c : f.children())
    if (!pred(c)) return false;
  return true;
}

// Literals and constants closed under & | X and the class's own operators.
bool in_class(const Formula& f, Op unary, Op binary1, Op binary2) {
  switch (f.op()) {
    case Op::True: case Op::False: case Op::Atom:
      return true;
    case Op::Not:
      return f[0].is(Op::Atom);
    case Op::And: case Op::Or: case Op::Next:
      return all_children(f, [&](const Formula& c) { return in_class(c, unary, binary1, binary2); });
    default:
      if (f.op() != unary && f.op() != binary1 && f.op() != binary2) return false;
      return all_children(f, [&](const Formula& c) { return in_class(c, unary, binary1, binary2); });
  }
}

}  // namespace

bool is_syntactic_safety(const Formula& f) { return in_class(f, Op::Globally, Op::Release, Op::WeakUntil); }

bool is_syntactic_guarantee(const Formula& f) { return in_class(f, Op::Finally, Op::Until, Op::StrongRelease); }

bool is_syntactic_obligation(const Formula& f) {
  if (is_syntactic_safety(f) || is_syntactic_guarantee(f)) return true;
  if (!f.is(Op::And) && !f.is(Op::Or) && !f.is(Op::Next)) return false;
  for (const Formula& c : f.children())
    if (!is_syntactic_obligation(c)) return false;
  return true;
}

}  // namespace rtamp::ltl
