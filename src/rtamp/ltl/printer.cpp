#include "rtamp/ltl/printer.hpp"

#include <algorithm>
#include <set>
#include <unordered_map>
#include <unordered_set>

#include "rtamp/util/error.hpp"

namespace rtamp::ltl {
namespace {

// Binding strength of a node when printed (higher binds tighter); mirrors the
// parser's table.
int strength(Op op) {
  switch (op) {
    case Op::Implies: case Op::Equiv: return 1;
    case Op::Or: return 2;
    case Op::Xor: return 3;
    case Op::And: return 4;
    case Op::Until: case Op::Release: case Op::WeakUntil: case Op::StrongRelease: return 5;
    case Op::Not: case Op::Next: case Op::Finally: case Op::Globally: return 6;
    default: return 7;
  }
}

const char* spot_infix(Op op) {
  switch (op) {
    case Op::And: return " & ";
    case Op::Or: return " | ";
    case Op::Xor: return " xor ";
    case Op::Implies: return " -> ";
    case Op::Equiv: return " <-> ";
    case Op::Until: return " U ";
    case Op::Release: return " R ";
    case Op::WeakUntil: return " W ";
    case Op::StrongRelease: return " M ";
    default: return " ? ";
  }
}

void print_atom(const std::string& name, std::string& out) {
  if (is_plain_atom_name(name)) {
    out += name;
    return;
  }
  out += '"';
  for (char c : name) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  out += '"';
}

void print(const Formula& f, std::string& out);

void print_child(const Formula& c, bool parens, std::string& out) {
  if (parens) out += '(';
  print(c, out);
  if (parens) out += ')';
}

void print(const Formula& f, std::string& out) {
  const Op op = f.op();
  switch (op) {
    case Op::True: out += '1'; return;
    case Op::False: out += '0'; return;
    case Op::Atom: print_atom(f.name(), out); return;
    case Op::Not: case Op::Next: case Op::Finally: case Op::Globally:
      out += op == Op::Not ? "!" : op_name(op);
      print_child(f[0], strength(f[0].op()) < 6, out);
      return;
    case Op::And: case Op::Or: {
      const int s = strength(op);
      bool first = true;
      for (const Formula& c : f.children()) {
        if (!first) out += spot_infix(op);
        first = false;
        print_child(c, strength(c.op()) <= s, out);
      }
      return;
    }
    case Op::Xor:  // left associative
      print_child(f[0], strength(f[0].op()) < 3, out);
      out += spot_infix(op);
      print_child(f[1], strength(f[1].op()) <= 3, out);
      return;
    default: {  // right associative: -> <-> U R W M
      const int s = strength(op);
      print_child(f[0], strength(f[0].op()) <= s, out);
      out += spot_infix(op);
      print_child(f[1], strength(f[1].op()) < s, out);
      return;
    }
  }
}

bool is_spin_keyword(const std::string& s) {
  static const std::unordered_set<std::string> kw = {
      "true", "false", "always", "eventually", "until", "release", "weakuntil", "stronguntil",
      "implies", "equivalent", "next", "and", "or", "not", "ltl"};
  return kw.count(s) != 0;
}

constexpr std::size_t kMaxSpinText = std::size_t{1} << 22;  // 4 MiB

struct SpinPrinter {
  std::map<std::string, std::string>* renamed;
  std::unordered_map<std::string, std::string> fresh_of;  // original -> fresh
  std::set<std::string> used;                            // every atom name of f
  int counter = 0;

  std::string atom(const std::string& name) {
    if (is_spin_atom_name(name)) return name;
    if (!renamed) throw Error("atomic proposition '" + name + "' is not a valid spin identifier");
    if (auto it = fresh_of.find(name); it != fresh_of.end()) return it->second;
    std::string fresh;
    do {
      fresh = "p_" + std::to_string(counter++);
    } while (used.count(fresh) || renamed->count(fresh));
    fresh_of.emplace(name, fresh);
    (*renamed)[fresh] = name;
    return fresh;
  }

  void operand(const Formula& f, std::string& out) {
    if (f.op() == Op::Atom || f.is_constant()) {
      print(f, out);
    } else {
      out += '(';
      print(f, out);
      out += ')';
    }
  }
  void bin(const Formula& a, const char* op, const Formula& b, std::string& out) {
    operand(a, out);
    out += op;
    operand(b, out);
  }

  void print(const Formula& f, std::string& out) {
    if (out.size() > kMaxSpinText)
      throw Error("formula too large for spin syntax (expanding W and M duplicates operands)");
    switch (f.op()) {
      case Op::True: out += "true"; return;
      case Op::False: out += "false"; return;
      case Op::Atom: out += atom(f.name()); return;
      case Op::Not: out += "!"; operand(f[0], out); return;
      case Op::Next: out += "X "; operand(f[0], out); return;
      case Op::Finally: out += "<> "; operand(f[0], out); return;
      case Op::Globally: out += "[] "; operand(f[0], out); return;
      case Op::And: case Op::Or: {
        bool first = true;
        for (const Formula& c : f.children()) {
          if (!first) out += f.op() == Op::And ? " && " : " || ";
          first = false;
          operand(c, out);
        }
        return;
      }
      case Op::Implies: bin(f[0], " -> ", f[1], out); return;
      case Op::Equiv: bin(f[0], " <-> ", f[1], out); return;
      case Op::Xor:
        out += "!(";
        bin(f[0], " <-> ", f[1], out);
        out += ')';
        return;
      case Op::Until: bin(f[0], " U ", f[1], out); return;
      case Op::Release: bin(f[0], " V ", f[1], out); return;
      case Op::WeakUntil:  // a W b = b V (a || b)
        operand(f[1], out);
        out += " V (";
        bin(f[0], " || ", f[1], out);
        out += ')';
        return;
      case Op::StrongRelease:  // a M b = b U (a && b)
        operand(f[1], out);
        out += " U (";
        bin(f[0], " && ", f[1], out);
        out += ')';
        return;
    }
  }
};

void collect_atoms(const Formula& f, std::set<std::string>& out, std::unordered_set<Formula>& seen) {
  if (!seen.insert(f).second) return;
  if (f.op() == Op::Atom) out.insert(f.name());
  for (const Formula& c : f.children()) collect_atoms(c, out, seen);
}

}  // namespace

bool is_plain_atom_name(const std::string& name) {
  if (name.empty()) return false;
  const char c0 = name[0];
  if (!((c0 >= 'a' && c0 <= 'z') || c0 == '_')) return false;
  for (char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.'))
      return false;
  }
  return name != "true" && name != "false" && name != "xor";
}

bool is_spin_atom_name(const std::string& name) {
  if (name.empty() || !(name[0] >= 'a' && name[0] <= 'z')) return false;
  for (char c : name) {
    if (!((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_')) return false;
  }
  return !is_spin_keyword(name);
}

std::string to_string(const Formula& f) {
  std::string out;
  out.reserve(std::min<std::size_t>(16 * f.size(), 1 << 16));
  print(f, out);
  return out;
}

std::string to_spin_string(const Formula& f, std::map<std::string, std::string>* renamed) {
  SpinPrinter p{renamed, {}, {}, 0};
  if (renamed) {
    std::unordered_set<Formula> seen;
    collect_atoms(f, p.used, seen);
  }
  std::string out;
  p.print(f, out);
  return out;
}

}  // namespace rtamp::ltl
