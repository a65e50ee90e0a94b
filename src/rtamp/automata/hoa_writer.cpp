#include "rtamp/automata/hoa_writer.hpp"

#include <ostream>
#include <sstream>
#include <vector>

#include "rtamp/automata/boolean_guard.hpp"

namespace rtamp::automata {

std::string hoa_quote(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    if (c == '\n') {
      out += "\\n";
      continue;
    }
    out += c;
  }
  out += '"';
  return out;
}

std::string hoa_cube(const Cube& c) {
  if (c.is_true()) return "t";
  std::string out;
  for (unsigned i = 0; i < kMaxAtoms; ++i) {
    const Letter bit = Letter{1} << i;
    if (!((c.pos | c.neg) & bit)) continue;
    if (!out.empty()) out += '&';
    if (c.neg & bit) out += '!';
    out += std::to_string(i);
  }
  return out;
}

namespace {

std::string marks_sig(Marks m) {
  std::string out = "{";
  bool first = true;
  for (unsigned i = 0; i < 32; ++i)
    if (m & (Marks{1} << i)) {
      if (!first) out += ' ';
      out += std::to_string(i);
      first = false;
    }
  return out + "}";
}

}  // namespace

void write_hoa(std::ostream& out, const Automaton& a) {
  const std::uint32_t n = a.num_states();
  out << "HOA: v1\n";
  if (!a.name.empty()) out << "name: " << hoa_quote(a.name) << "\n";
  out << "States: " << n << "\n";
  if (n > 0) out << "Start: " << a.initial << "\n";
  out << "AP: " << a.atoms.size();
  for (const auto& p : a.atoms) out << ' ' << hoa_quote(p);
  out << "\n";
  const bool sb = a.state_based;
  const std::uint32_t sets = sb ? 1 : a.num_sets;
  if (sets == 0) {
    out << "acc-name: all\nAcceptance: 0 t\n";
  } else if (sets == 1) {
    out << "acc-name: Buchi\nAcceptance: 1 Inf(0)\n";
  } else {
    out << "acc-name: generalized-Buchi " << sets << "\nAcceptance: " << sets << ' ';
    for (std::uint32_t i = 0; i < sets; ++i) out << (i ? "&" : "") << "Inf(" << i << ")";
    out << "\n";
  }
  out << "properties: trans-labels explicit-labels " << (sb ? "state-acc" : "trans-acc") << "\n";
  out << "--BODY--\n";
  const Marks keep = sb ? Marks{0} : a.all_marks();
  struct Group {
    std::uint32_t dst;
    Marks marks;
    std::vector<Cube> cubes;
  };
  std::vector<Group> groups;
  for (std::uint32_t q = 0; q < n; ++q) {
    out << "State: " << q;
    if (sb && a.state_accepting[q]) out << " {0}";
    out << "\n";
    groups.clear();
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
      out << '[';
      bool any_true = false;
      for (const Cube& c : g.cubes) any_true |= c.is_true();
      if (any_true) {
        out << 't';
      } else {
        for (std::size_t i = 0; i < g.cubes.size(); ++i) out << (i ? " | " : "") << hoa_cube(g.cubes[i]);
      }
      out << "] " << g.dst;
      if (!sb && g.marks) out << ' ' << marks_sig(g.marks);
      out << "\n";
    }
  }
  out << "--END--\n";
}

std::string to_hoa(const Automaton& a) {
  std::ostringstream os;
  write_hoa(os, a);
  return os.str();
}

}  // namespace rtamp::automata
