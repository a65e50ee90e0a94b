#include "rtamp/automata/dot_writer.hpp"

#include <ostream>
#include <sstream>
#include <vector>

#include "rtamp/automata/boolean_guard.hpp"

namespace rtamp::automata {

namespace {

std::string dot_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  return out;
}

std::string marks_text(Marks m) {
  std::string out = "{";
  bool first = true;
  for (unsigned i = 0; i < 32; ++i)
    if (m & (Marks{1} << i)) {
      if (!first) out += ',';
      out += std::to_string(i);
      first = false;
    }
  return out + "}";
}

}  // namespace

std::string cube_to_string(const Cube& c, const std::vector<std::string>& atoms) {
  if (c.is_true()) return "true";
  std::string out;
  for (std::size_t i = 0; i < kMaxAtoms; ++i) {
    const Letter bit = Letter{1} << i;
    if (!((c.pos | c.neg) & bit)) continue;
    if (!out.empty()) out += " & ";
    if (c.neg & bit) out += '!';
    out += i < atoms.size() ? atoms[i] : "p" + std::to_string(i);
  }
  return out;
}

void write_dot(std::ostream& out, const Automaton& a) {
  out << "digraph \"" << dot_escape(a.name) << "\" {\n";
  out << "  rankdir=LR;\n";
  if (!a.name.empty()) out << "  label=\"" << dot_escape(a.name) << "\";\n  labelloc=\"t\";\n";
  out << "  node [shape=circle, fontname=\"Helvetica\"];\n  edge [fontname=\"Helvetica\"];\n";
  const std::uint32_t n = a.num_states();
  if (n > 0) out << "  I [label=\"\", shape=none, width=0, height=0];\n  I -> " << a.initial << ";\n";
  for (std::uint32_t q = 0; q < n; ++q) {
    out << "  " << q << " [label=\"" << q << "\"";
    if (a.is_accepting_state(q)) out << ", shape=doublecircle";
    out << "];\n";
  }
  struct Group {
    std::uint32_t dst;
    Marks marks;
    std::vector<Cube> cubes;
  };
  const Marks keep = a.state_based ? Marks{0} : a.all_marks();
  for (std::uint32_t q = 0; q < n; ++q) {
    std::vector<Group> groups;
    for (const Edge& e : a.edges[q]) {
      if (e.guard.is_false()) continue;
      const Marks m = e.marks & keep;
      bool merged = false;
      for (Group& g : groups)
        if (g.dst == e.dst && g.marks == m) {
          g.cubes.push_back(e.guard);
          merged = true;
          break;
        }
      if (!merged) groups.push_back({e.dst, m, {e.guard}});
    }
    for (Group& g : groups) simplify_cubes(g.cubes);
    for (const Group& g : groups) {
      std::string label;
      bool any_true = false;
      for (const Cube& c : g.cubes) any_true |= c.is_true();
      if (any_true) {
        label = "true";
      } else {
        for (std::size_t i = 0; i < g.cubes.size(); ++i) {
          if (i) label += " | ";
          const bool paren = g.cubes.size() > 1 && __builtin_popcountll(g.cubes[i].pos | g.cubes[i].neg) > 1;
          label += paren ? "(" + cube_to_string(g.cubes[i], a.atoms) + ")" : cube_to_string(g.cubes[i], a.atoms);
        }
      }
      if (g.marks) label += " " + marks_text(g.marks);
      out << "  " << q << " -> " << g.dst << " [label=\"" << dot_escape(label) << "\"];\n";
    }
  }
  out << "}\n";
}

std::string to_dot(const Automaton& a) {
  std::ostringstream os;
  write_dot(os, a);
  return os.str();
}

}  // namespace rtamp::automata
