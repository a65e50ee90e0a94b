#include "rtamp/automata/never_claim_writer.hpp"

#include <cctype>
#include <ostream>
#include <sstream>
#include <vector>

#include "rtamp/automata/boolean_guard.hpp"

#include "rtamp/util/error.hpp"

namespace rtamp::automata {

namespace {

bool promela_identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
  for (char c : s)
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
  static const char* const reserved[] = {"true", "false", "skip", "if", "fi", "do", "od", "goto", "never",
                                         "atomic", "assert", "else", "break", "init", "proctype", "timeout"};
  for (const char* r : reserved)
    if (s == r) return false;
  return true;
}

std::string cube_text(const Cube& c, const std::vector<std::string>& atoms) {
  if (c.is_true()) return "(1)";
  std::string out = "(";
  bool first = true;
  for (std::size_t i = 0; i < atoms.size(); ++i) {
    const Letter bit = Letter{1} << i;
    if (!((c.pos | c.neg) & bit)) continue;
    if (!first) out += " && ";
    first = false;
    if (c.neg & bit) out += '!';
    out += atoms[i];
  }
  return out + ")";
}

std::string comment_safe(const std::string& s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '*' && i + 1 < s.size() && s[i + 1] == '/') {
      out += "* /";
      ++i;
    } else if (s[i] == '\n') {
      out += ' ';
    } else {
      out += s[i];
    }
  }
  return out;
}

}  // namespace

void write_never_claim(std::ostream& out, const Automaton& a) {
  if (!a.state_based)
    throw Error("never claims need a state-based Büchi automaton (do not combine --gba with --format never)");
  for (const auto& p : a.atoms)
    if (!promela_identifier(p))
      throw Error("atom '" + p + "' is not a Promela identifier, so it cannot appear in a never claim");
  const std::uint32_t n = a.num_states();
  auto name = [&](std::uint32_t q) {
    const bool acc = a.state_accepting[q];
    if (q == a.initial) return std::string(acc ? "accept_init" : "T0_init");
    return std::string(acc ? "accept_S" : "T0_S") + std::to_string(q);
  };
  out << "never { /* " << comment_safe(a.name) << " */\n";
  std::vector<std::uint32_t> order;
  if (n > 0) order.push_back(a.initial);
  for (std::uint32_t q = 0; q < n; ++q)
    if (q != a.initial) order.push_back(q);
  struct Group {
    std::uint32_t dst;
    std::vector<Cube> cubes;
  };
  for (std::uint32_t q : order) {
    out << name(q) << ":\n";
    std::vector<Group> groups;
    for (const Edge& e : a.edges[q]) {
      if (e.guard.is_false()) continue;
      bool merged = false;
      for (Group& g : groups)
        if (g.dst == e.dst) {
          g.cubes.push_back(e.guard);
          merged = true;
          break;
        }
      if (!merged) groups.push_back({e.dst, {e.guard}});
    }
    if (groups.empty()) {
      out << "\tfalse;\n";
      continue;
    }
    out << "\tif\n";
    for (Group& g : groups) simplify_cubes(g.cubes);
    for (const Group& g : groups) {
      out << "\t:: ";
      bool any_true = false;
      for (const Cube& c : g.cubes) any_true |= c.is_true();
      if (any_true || g.cubes.size() == 1) {
        out << (any_true ? "(1)" : cube_text(g.cubes[0], a.atoms));
      } else {
        out << '(';
        for (std::size_t i = 0; i < g.cubes.size(); ++i) out << (i ? " || " : "") << cube_text(g.cubes[i], a.atoms);
        out << ')';
      }
      out << " -> goto " << name(g.dst) << "\n";
    }
    out << "\tfi;\n";
  }
  out << "}\n";
}

std::string to_never_claim(const Automaton& a) {
  std::ostringstream os;
  write_never_claim(os, a);
  return os.str();
}

}  // namespace rtamp::automata
