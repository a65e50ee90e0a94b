#include "rtamp/automata/shortcuts.hpp"

#include <algorithm>

#include "rtamp/automata/reduce.hpp"
#include "rtamp/automata/vwaa.hpp"

namespace rtamp::automata::detail {

using ltl::Formula;
using ltl::Op;

namespace {

bool cubes_rec(const Formula& f, const std::vector<std::string>& atoms, std::vector<Cube>& out, std::size_t max) {
  switch (f.op()) {
    case Op::True: out.assign(1, Cube{}); return true;
    case Op::False: out.clear(); return true;
    case Op::Atom:
    case Op::Not: {
      const bool neg = f.is(Op::Not);
      const std::string& name = neg ? f[0].name() : f.name();
      const auto it = std::lower_bound(atoms.begin(), atoms.end(), name);
      const Letter bit = Letter{1} << (it - atoms.begin());
      out.assign(1, neg ? Cube{0, bit} : Cube{bit, 0});
      return true;
    }
    case Op::Or: {
      out.clear();
      std::vector<Cube> c;
      for (const Formula& g : f.children()) {
        if (!cubes_rec(g, atoms, c, max)) return false;
        out.insert(out.end(), c.begin(), c.end());
        if (out.size() > max) return false;
      }
      return true;
    }
    case Op::And: {
      out.assign(1, Cube{});
      std::vector<Cube> c, next;
      for (const Formula& g : f.children()) {
        if (!cubes_rec(g, atoms, c, max)) return false;
        next.clear();
        for (const Cube& x : out)
          for (const Cube& y : c) {
            const Cube z = x & y;
            if (!z.is_false()) next.push_back(z);
          }
        if (next.size() > max) return false;
        out.swap(next);
      }
      return true;
    }
    default:
      return false;
  }
}

Automaton skeleton(const std::vector<std::string>& atoms, bool state_based, std::uint32_t sets) {
  Automaton a;
  a.atoms = atoms;
  a.state_based = state_based;
  a.num_sets = state_based ? 1 : sets;
  return a;
}

}  // namespace

bool boolean_cubes(const Formula& f, const std::vector<std::string>& atoms, std::vector<Cube>& cubes,
                   std::size_t max_cubes) {
  if (!f.is_boolean()) return false;
  if (!cubes_rec(f, atoms, cubes, max_cubes)) return false;
  Automaton tmp;  // reuse merge_parallel_edges for cube minimisation
  tmp.add_state();
  for (const Cube& c : cubes) tmp.edges[0].push_back(Edge{0, c, 0});
  merge_parallel_edges(tmp);
  cubes.clear();
  for (const Edge& e : tmp.edges[0]) cubes.push_back(e.guard);
  return true;
}

bool try_shortcut(const Formula& f, bool sb, Automaton& out) {
  const std::vector<std::string> atoms = atoms_of(f);
  if (atoms.size() > kMaxAtoms) return false;
  std::vector<Cube> b;
  auto accepting_sink = [&](Automaton& a) {
    const std::uint32_t s = a.add_state(true);
    a.add_edge(s, s, Cube{}, sb ? 1u : 0u);
    return s;
  };
  if (f.is_boolean()) {
    if (!boolean_cubes(f, atoms, b)) return false;
    Automaton a = skeleton(atoms, sb, 0);
    if (b.empty()) {
      a.initial = a.add_state(false);
    } else if (b.size() == 1 && b[0].is_true()) {
      a.initial = accepting_sink(a);
    } else {
      a.initial = a.add_state(true);
      const std::uint32_t s = accepting_sink(a);
      for (const Cube& c : b) a.add_edge(a.initial, s, c);
    }
    out = std::move(a);
    return true;
  }
  const bool unary = f.is(Op::Globally) || f.is(Op::Finally);
  if (!unary) return false;
  const Formula& c = f[0];
  if (c.is_boolean()) {
    if (!boolean_cubes(c, atoms, b) || b.empty()) return false;
    if (f.is(Op::Globally)) {  // G b
      Automaton a = skeleton(atoms, sb, 0);
      a.initial = a.add_state(true);
      for (const Cube& x : b) a.add_edge(0, 0, x, sb ? 1u : 0u);
      out = std::move(a);
      return true;
    }
    // F b
    Automaton a = skeleton(atoms, sb, 1);
    a.initial = a.add_state(false);
    a.add_edge(0, 0, Cube{}, 0);
    const std::uint32_t s = a.add_state(true);
    a.add_edge(s, s, Cube{}, 1);
    for (const Cube& x : b) a.add_edge(0, s, x);
    out = std::move(a);
    return true;
  }
  const bool gf = f.is(Op::Globally) && c.is(Op::Finally);
  const bool fg = f.is(Op::Finally) && c.is(Op::Globally);
  if (!(gf || fg) || !c[0].is_boolean()) return false;
  if (!boolean_cubes(c[0], atoms, b) || b.empty()) return false;
  Automaton a = skeleton(atoms, sb, 1);
  if (gf) {
    if (!sb) {
      a.initial = a.add_state(false);
      a.add_edge(0, 0, Cube{}, 0);
      for (const Cube& x : b) a.add_edge(0, 0, x, 1);
    } else {
      a.initial = a.add_state(false);
      const std::uint32_t s = a.add_state(true);
      for (std::uint32_t q : {a.initial, s}) {
        a.add_edge(q, a.initial, Cube{});
        for (const Cube& x : b) a.add_edge(q, s, x);
      }
    }
  } else {
    a.initial = a.add_state(false);
    a.add_edge(0, 0, Cube{}, 0);
    const std::uint32_t s = a.add_state(true);
    for (const Cube& x : b) {
      a.add_edge(0, s, x);
      a.add_edge(s, s, x, 1);
    }
  }
  out = std::move(a);
  return true;
}

}  // namespace rtamp::automata::detail
