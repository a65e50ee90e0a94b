#include "rtamp/automata/automaton.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::automata {

std::size_t Automaton::num_edges() const {
  std::size_t n = 0;
  for (const auto& out : edges) n += out.size();
  return n;
}

std::uint32_t Automaton::add_state(bool accepting) {
  edges.emplace_back();
  state_accepting.push_back(accepting);
  return num_states() - 1;
}

void Automaton::add_edge(std::uint32_t src, std::uint32_t dst, Cube guard, Marks marks) {
  if (state_based) marks = state_accepting[src] ? 1u : 0u;
  edges[src].push_back(Edge{dst, guard, marks});
}

std::uint32_t Automaton::atom_index(const std::string& atom) {
  if (int i = find_atom(atom); i >= 0) return static_cast<std::uint32_t>(i);
  if (atoms.size() >= kMaxAtoms)
    throw Error("too many atomic propositions (at most " + std::to_string(kMaxAtoms) + ")", {}, {});
  atoms.push_back(atom);
  return static_cast<std::uint32_t>(atoms.size() - 1);
}

int Automaton::find_atom(const std::string& atom) const {
  for (std::size_t i = 0; i < atoms.size(); ++i)
    if (atoms[i] == atom) return static_cast<int>(i);
  return -1;
}

bool is_deterministic(const Automaton& a) {
  for (const auto& out : a.edges)
    for (std::size_t i = 0; i < out.size(); ++i)
      for (std::size_t j = i + 1; j < out.size(); ++j)
        if (!(out[i].guard & out[j].guard).is_false()) return false;
  return true;
}

}  // namespace rtamp::automata
