// Büchi automata over 2^AP (paper Definition 2), the type the planner uses.
//
// One representation serves both forms the project needs:
//  - transition-based generalized Büchi (TGBA): every edge carries a set of
//    acceptance marks (bit i = set i); a run is accepting iff it visits every
//    set 0..num_sets-1 infinitely often. num_sets == 0 means every infinite
//    run is accepting (acceptance "t").
//  - state-based Büchi (BA, the default output and what the planner searches):
//    state_based == true, num_sets == 1, and every edge leaving state q carries
//    exactly the marks of q (state_accepting[q] ? {0} : {}).
//
// Letters are valuations of the atoms: bit i of a Letter is atom i (atoms[i]).
// At most 64 atoms. Guards are cubes (conjunctions of literals); a DNF guard is
// several edges with the same source and destination.
// Invariants: initial < num_states(); every edge's dst < num_states();
// a cube never has an atom both in pos and in neg.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rtamp::automata {

using Letter = std::uint64_t;
using Marks = std::uint32_t;
constexpr std::size_t kMaxAtoms = 64;

struct Cube {
  Letter pos = 0;  // atoms that must be true
  Letter neg = 0;  // atoms that must be false
  bool matches(Letter l) const { return (l & pos) == pos && (l & neg) == 0; }
  bool is_true() const { return pos == 0 && neg == 0; }
  // Conjunction; is_false() tells whether the result is contradictory.
  Cube operator&(const Cube& o) const { return {pos | o.pos, neg | o.neg}; }
  bool is_false() const { return (pos & neg) != 0; }
  // `*this` implies `o` (every letter matching this matches o).
  bool implies(const Cube& o) const { return (o.pos & ~pos) == 0 && (o.neg & ~neg) == 0; }
  friend bool operator==(const Cube&, const Cube&) = default;
};

struct Edge {
  std::uint32_t dst = 0;
  Cube guard;
  Marks marks = 0;
  friend bool operator==(const Edge&, const Edge&) = default;
};

class Automaton {
 public:
  std::vector<std::string> atoms;          // bit i of a Letter is atoms[i]
  std::uint32_t initial = 0;
  std::uint32_t num_sets = 1;              // generalized Büchi: Inf(0) & ... & Inf(num_sets-1)
  bool state_based = false;                // see header comment
  std::vector<std::vector<Edge>> edges;    // out-edges, per state
  std::vector<bool> state_accepting;       // per state; meaningful when state_based
  std::string name;                        // usually the formula it came from

  std::uint32_t num_states() const { return static_cast<std::uint32_t>(edges.size()); }
  std::size_t num_edges() const;
  std::uint32_t add_state(bool accepting = false);
  void add_edge(std::uint32_t src, std::uint32_t dst, Cube guard, Marks marks = 0);
  // Index of an atom, adding it if new. Throws rtamp::Error past kMaxAtoms.
  std::uint32_t atom_index(const std::string& atom);
  // -1 if absent.
  int find_atom(const std::string& atom) const;
  // Sets 0..n-1 as marks.
  static Marks marks_below(std::uint32_t n) { return n >= 32 ? ~Marks{0} : ((Marks{1} << n) - 1); }
  Marks all_marks() const { return marks_below(num_sets); }
  // The acceptance sets its edges' marks speak of: num_sets, or one when state-based
  // (the edges leaving an accepting state carry set 0).
  std::uint32_t edge_sets() const { return state_based ? 1u : num_sets; }
  // State-based: q is accepting. Transition-based automata: false.
  bool is_accepting_state(std::uint32_t q) const { return state_based && state_accepting[q]; }
  // Büchi acceptance as a property of edges (state-based, or num_sets <= 1):
  // a cycle is accepting iff it takes an edge for which this holds. State-based:
  // the edge enters an accepting state; one set: the edge carries it; none: any.
  bool accepting_edge(const Edge& e) const {
    return state_based ? bool(state_accepting[e.dst]) : num_sets == 0 || (e.marks & 1u) != 0;
  }
  // Generalized Büchi acceptance as a property of edges, for every form: a
  // cycle is accepting iff the union of its edges' cycle_marks is
  // cycle_marks_all(). State-based: {0} when the edge enters an accepting
  // state; no set: {0} on every edge; otherwise the edge's marks.
  Marks cycle_marks(const Edge& e) const {
    return state_based ? (state_accepting[e.dst] ? 1u : 0u) : num_sets == 0 ? 1u : (e.marks & all_marks());
  }
  Marks cycle_marks_all() const { return state_based || num_sets == 0 ? 1u : all_marks(); }
};

// No state has two edges whose guards share a letter.
bool is_deterministic(const Automaton& a);

}  // namespace rtamp::automata
