#include "rtamp/ltl/parser.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string>
#include <vector>

namespace rtamp::ltl {
namespace {

enum class Tok : std::uint8_t {
  Atom, True, False, LParen, RParen,
  Not, Next, Finally, Globally,                      // prefix
  And, Or, Xor, Implies, Equiv, Until, Release, WeakUntil, StrongRelease,  // infix
  End,
};

struct Token {
  Tok kind = Tok::End;
  std::size_t pos = 0;  // byte offset of the first character
  std::size_t len = 0;
  std::string text;     // atom name (unescaped) for Tok::Atom
};

bool is_prefix(Tok t) { return t == Tok::Not || t == Tok::Next || t == Tok::Finally || t == Tok::Globally; }
bool is_infix(Tok t) { return t >= Tok::And && t <= Tok::StrongRelease; }

// Binding strength, loosest first, as in Spot's grammar.
int precedence(Tok t) {
  switch (t) {
    case Tok::Implies: case Tok::Equiv: return 1;
    case Tok::Or: return 2;
    case Tok::Xor: return 3;
    case Tok::And: return 4;
    case Tok::Until: case Tok::Release: case Tok::WeakUntil: case Tok::StrongRelease: return 5;
    default: return 6;  // prefix operators
  }
}
bool right_assoc(int prec) { return prec == 1 || prec == 5; }

Op to_op(Tok t) {
  switch (t) {
    case Tok::Not: return Op::Not;
    case Tok::Next: return Op::Next;
    case Tok::Finally: return Op::Finally;
    case Tok::Globally: return Op::Globally;
    case Tok::And: return Op::And;
    case Tok::Or: return Op::Or;
    case Tok::Xor: return Op::Xor;
    case Tok::Implies: return Op::Implies;
    case Tok::Equiv: return Op::Equiv;
    case Tok::Until: return Op::Until;
    case Tok::Release: return Op::Release;
    case Tok::WeakUntil: return Op::WeakUntil;
    case Tok::StrongRelease: return Op::StrongRelease;
    default: return Op::False;
  }
}

bool is_lower_start(char c) { return (c >= 'a' && c <= 'z') || c == '_'; }
bool is_ident_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
}

class Parser {
 public:
  Parser(std::string_view src, const SourceLocation& origin) : src_(src), origin_(origin) {}

  Formula run();
  std::vector<AtomOccurrence> atoms();

 private:
  struct Operand {
    Formula f;                  // the value, unless `list` is non-empty
    Op pending = Op::False;     // And/Or while operands are being collected
    std::vector<Formula> list;  // operands of a pending n-ary And/Or
  };
  struct Pending {
    Tok kind;
    std::size_t pos;
    std::size_t len;
  };

  [[noreturn]] void fail(std::size_t at, const std::string& what) const;
  SourceLocation where_of(std::size_t at) const;
  Token next();
  std::string describe(const Token& t) const;
  void check_depth(const Formula& f, std::size_t at) const {
    if (f.depth() > static_cast<std::size_t>(kMaxParseDepth)) fail(at, "formula too deeply nested");
  }
  void materialize(Operand& o, std::size_t at) const {
    if (o.list.empty()) return;
    o.f = Formula::nary(o.pending, std::move(o.list));
    o.list.clear();
    o.pending = Op::False;
    check_depth(o.f, at);
  }
  void reduce();

  std::string_view src_;
  SourceLocation origin_;
  std::size_t pos_ = 0;
  std::vector<Pending> ops_;
  std::vector<Operand> operands_;
  int parens_ = 0;
};

void Parser::fail(std::size_t at, const std::string& what) const {
  throw Error(what, where_of(at), caret_at(src_, at));  // the line around the column, at most ~120 characters
}

SourceLocation Parser::where_of(std::size_t at) const {
  if (at > src_.size()) at = src_.size();
  std::size_t line_start = 0;
  int line = 1;
  for (std::size_t i = 0; i < at; ++i) {
    if (src_[i] == '\n') {
      ++line;
      line_start = i + 1;
    }
  }
  const int column = static_cast<int>(at - line_start) + 1;
  SourceLocation where = origin_;
  if (origin_.line > 0) {
    where.line = origin_.line + line - 1;
    where.column = (line == 1 && origin_.column > 0) ? origin_.column + column - 1 : column;
  } else {
    where.line = line;
    where.column = column;
  }
  return where;
}

std::vector<AtomOccurrence> Parser::atoms() {
  std::vector<AtomOccurrence> out;
  for (Token t = next(); t.kind != Tok::End; t = next()) {
    if (t.kind != Tok::Atom) continue;
    AtomOccurrence a;
    a.name = std::move(t.text);
    a.quoted = src_[t.pos] == '"';
    a.offset = t.pos;
    a.length = t.len;
    a.where = where_of(t.pos);
    out.push_back(std::move(a));
  }
  return out;
}

std::string Parser::describe(const Token& t) const {
  if (t.kind == Tok::End) return "end of formula";
  std::string out = "'";
  out.append(src_.data() + t.pos, std::min(t.len, src_.size() - t.pos));
  out += '\'';
  return out;
}

Token Parser::next() {
  const std::size_t n = src_.size();
  while (pos_ < n && (src_[pos_] == ' ' || src_[pos_] == '\t' || src_[pos_] == '\n' || src_[pos_] == '\r')) ++pos_;
  Token t;
  t.pos = pos_;
  if (pos_ >= n) return t;
  const char c = src_[pos_];
  const char d = pos_ + 1 < n ? src_[pos_ + 1] : '\0';
  const char e = pos_ + 2 < n ? src_[pos_ + 2] : '\0';
  auto op = [&](Tok k, std::size_t len) {
    t.kind = k;
    t.len = len;
    pos_ += len;
    return t;
  };
  switch (c) {
    case '(': return op(Tok::LParen, 1);
    case ')': return op(Tok::RParen, 1);
    case '!': case '~': return op(Tok::Not, 1);
    case '^': return op(Tok::Xor, 1);
    case '&': return op(Tok::And, d == '&' ? 2 : 1);
    case '|': return op(Tok::Or, d == '|' ? 2 : 1);
    case '/':
      if (d == '\\') return op(Tok::And, 2);
      break;
    case '\\':
      if (d == '/') return op(Tok::Or, 2);
      break;
    case '-':
      if (d == '>') return op(Tok::Implies, 2);
      break;
    case '=':
      if (d == '>') return op(Tok::Implies, 2);
      break;
    case '<':
      if (d == '-' && e == '>') return op(Tok::Equiv, 3);
      if (d == '=' && e == '>') return op(Tok::Equiv, 3);
      if (d == '>') return op(Tok::Finally, 2);
      break;
    case '[':
      if (d == ']') return op(Tok::Globally, 2);
      break;
    case 'X': return op(Tok::Next, 1);
    case 'F': return op(Tok::Finally, 1);
    case 'G': return op(Tok::Globally, 1);
    case 'U': return op(Tok::Until, 1);
    case 'R': case 'V': return op(Tok::Release, 1);
    case 'W': return op(Tok::WeakUntil, 1);
    case 'M': return op(Tok::StrongRelease, 1);
    case '"': {
      std::size_t i = pos_ + 1;
      std::string name;
      while (i < n && src_[i] != '"') {
        if (src_[i] == '\\' && i + 1 < n) ++i;
        name += src_[i];
        ++i;
      }
      if (i >= n) fail(pos_, "unterminated quoted atomic proposition");
      if (name.empty()) fail(pos_, "empty quoted atomic proposition");
      t.kind = Tok::Atom;
      t.len = i + 1 - pos_;
      t.text = std::move(name);
      pos_ = i + 1;
      return t;
    }
    default:
      break;
  }
  if (c >= '0' && c <= '9') {
    std::size_t i = pos_;
    while (i < n && is_ident_char(src_[i])) ++i;
    const std::string_view num = src_.substr(pos_, i - pos_);
    if (num == "0") return op(Tok::False, 1);
    if (num == "1") return op(Tok::True, 1);
    fail(pos_, "unexpected '" + std::string(num) + "' (the only numbers are the constants 0 and 1)");
  }
  if (is_lower_start(c)) {
    std::size_t i = pos_;
    while (i < n && is_ident_char(src_[i])) ++i;
    const std::string_view word = src_.substr(pos_, i - pos_);
    if (word == "true") return op(Tok::True, 4);
    if (word == "false") return op(Tok::False, 5);
    if (word == "xor") return op(Tok::Xor, 3);
    t.kind = Tok::Atom;
    t.len = word.size();
    t.text = std::string(word);
    pos_ = i;
    return t;
  }
  if (c >= 'A' && c <= 'Z') {
    fail(pos_, std::string("unexpected '") + c +
                   "': the upper-case operators are X F G U R V W M; atomic propositions start with a "
                   "lower-case letter or '_' (quote other names)");
  }
  if (static_cast<unsigned char>(c) >= 0x21 && static_cast<unsigned char>(c) < 0x7f)
    fail(pos_, std::string("unexpected character '") + c + "'");
  char buf[48];
  std::snprintf(buf, sizeof buf, "unexpected byte 0x%02x", static_cast<unsigned>(static_cast<unsigned char>(c)));
  fail(pos_, buf);
}

void Parser::reduce() {
  const Pending top = ops_.back();
  ops_.pop_back();
  if (is_prefix(top.kind)) {
    Operand& a = operands_.back();
    materialize(a, top.pos);
    a.f = Formula::unary(to_op(top.kind), std::move(a.f));
    check_depth(a.f, top.pos);
    return;
  }
  Operand rhs = std::move(operands_.back());
  operands_.pop_back();
  Operand& lhs = operands_.back();
  materialize(rhs, top.pos);
  const Op o = to_op(top.kind);
  if (o == Op::And || o == Op::Or) {
    if (lhs.list.empty() || lhs.pending != o) {
      materialize(lhs, top.pos);
      lhs.list.reserve(4);
      lhs.list.push_back(std::move(lhs.f));
      lhs.pending = o;
    }
    lhs.list.push_back(std::move(rhs.f));
    // The depth of the n-ary node is max(child depth) + 1.
    if (lhs.list.back().depth() + 1 > static_cast<std::size_t>(kMaxParseDepth))
      fail(top.pos, "formula too deeply nested");
    return;
  }
  materialize(lhs, top.pos);
  lhs.f = Formula::binary(o, std::move(lhs.f), std::move(rhs.f));
  check_depth(lhs.f, top.pos);
}

Formula Parser::run() {
  bool expect_operand = true;
  for (;;) {
    Token t = next();
    if (expect_operand) {
      switch (t.kind) {
        case Tok::Atom:
          operands_.push_back({Formula::atom(t.text)});
          expect_operand = false;
          break;
        case Tok::True:
          operands_.push_back({Formula::tt()});
          expect_operand = false;
          break;
        case Tok::False:
          operands_.push_back({Formula::ff()});
          expect_operand = false;
          break;
        case Tok::LParen:
          if (++parens_ > kMaxParseDepth) fail(t.pos, "formula too deeply nested");
          ops_.push_back({t.kind, t.pos, t.len});
          break;
        case Tok::End:
          if (ops_.empty()) fail(t.pos, "empty formula");
          fail(t.pos, "unexpected end of formula, expected an operand after " +
                          describe(Token{ops_.back().kind, ops_.back().pos, ops_.back().len, {}}));
        default:
          if (is_prefix(t.kind)) {
            if (static_cast<int>(ops_.size()) - parens_ >= kMaxParseDepth) fail(t.pos, "formula too deeply nested");
            ops_.push_back({t.kind, t.pos, t.len});
            break;
          }
          fail(t.pos, "expected a formula before " + describe(t));
      }
      continue;
    }
    if (is_infix(t.kind)) {
      const int p = precedence(t.kind);
      while (!ops_.empty() && ops_.back().kind != Tok::LParen) {
        const int q = precedence(ops_.back().kind);
        if (q > p || (q == p && !right_assoc(p))) {
          reduce();
        } else {
          break;
        }
      }
      if (static_cast<int>(ops_.size()) - parens_ >= kMaxParseDepth) fail(t.pos, "formula too deeply nested");
      ops_.push_back({t.kind, t.pos, t.len});
      expect_operand = true;
      continue;
    }
    if (t.kind == Tok::RParen) {
      while (!ops_.empty() && ops_.back().kind != Tok::LParen) reduce();
      if (ops_.empty()) fail(t.pos, "unmatched ')'");
      ops_.pop_back();
      --parens_;
      materialize(operands_.back(), t.pos);
      continue;
    }
    if (t.kind == Tok::End) {
      while (!ops_.empty()) {
        if (ops_.back().kind == Tok::LParen) fail(ops_.back().pos, "missing ')' for this '('");
        reduce();
      }
      materialize(operands_.back(), t.pos);
      return std::move(operands_.back().f);
    }
    fail(t.pos, "expected an operator or ')' before " + describe(t));
  }
}

}  // namespace

Formula parse(std::string_view text) { return Parser(text, SourceLocation{}).run(); }

Formula parse(std::string_view text, const SourceLocation& origin) { return Parser(text, origin).run(); }

std::vector<AtomOccurrence> atom_occurrences(std::string_view text, const SourceLocation& origin) {
  return Parser(text, origin).atoms();
}

}  // namespace rtamp::ltl
