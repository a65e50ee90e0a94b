#include "rtamp/world/propositions.hpp"

#include "rtamp/world/suggest.hpp"

#include <cctype>
#include <cstdint>

namespace rtamp::world {

namespace {

constexpr int kMaxDepth = 200;       // nesting of '(' and '!' (keeps recursion bounded)
constexpr int kMaxCount = 1000000;   // largest INT in `count`

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

enum class Tok { Ident, Int, Not, And, Or, LParen, RParen, Cmp, End };

struct Token {
  Tok kind = Tok::End;
  std::string_view text;
  std::size_t offset = 0;  // byte offset into the expression
  PropExpr::Cmp cmp = PropExpr::Cmp::Ge;
};

class Parser {
 public:
  Parser(std::string_view text, const SourceLocation& where, const TextLayout& layout)
      : text_(text), where_(where), layout_(layout) {
    advance();
  }

  PropExpr parse() {
    PropExpr e = parse_or(0);
    if (tok_.kind != Tok::End) {
      if (tok_.kind == Tok::RParen) fail(tok_.offset, "unmatched ')'");
      fail(tok_.offset, "expected '&', '|' or the end of the expression, found " + describe(tok_));
    }
    return e;
  }

 private:
  [[noreturn]] void fail(std::size_t offset, const std::string& what) const {
    SourceLocation at = where_;
    int column = static_cast<int>(offset) + 1;
    if (at.line > 0 && at.column > 0) {
      if (auto l = layout_.locate(at.file, offset))
        at = *l;
      else
        at.column += static_cast<int>(offset);
    }
    std::string line(text_);
    for (char& c : line)
      if (c == '\n' || c == '\r') c = ' ';
    throw Error("in proposition expression: " + what, at, caret_line(line, column));
  }

  static std::string describe(const Token& t) {
    if (t.kind == Tok::End) return "the end of the expression";
    return quoted(t.text);
  }

  void advance() {
    std::size_t i = pos_;
    while (i < text_.size() && (text_[i] == ' ' || text_[i] == '\t' || text_[i] == '\n' || text_[i] == '\r')) ++i;
    tok_ = Token{};
    tok_.offset = i;
    if (i >= text_.size()) {
      tok_.kind = Tok::End;
      pos_ = i;
      return;
    }
    const char c = text_[i];
    auto take = [&](Tok k, std::size_t n) {
      tok_.kind = k;
      tok_.text = text_.substr(i, n);
      pos_ = i + n;
    };
    auto next_is = [&](char d) { return i + 1 < text_.size() && text_[i + 1] == d; };
    if (ident_start(c)) {
      std::size_t j = i;
      while (j < text_.size() && ident_char(text_[j])) ++j;
      take(Tok::Ident, j - i);
    } else if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t j = i;
      while (j < text_.size() && std::isdigit(static_cast<unsigned char>(text_[j]))) ++j;
      if (j < text_.size() && ident_char(text_[j])) fail(j, "unexpected " + quoted(text_.substr(j, 1)) + " in a number");
      take(Tok::Int, j - i);
    } else if (c == '(') {
      take(Tok::LParen, 1);
    } else if (c == ')') {
      take(Tok::RParen, 1);
    } else if (c == '&') {
      take(Tok::And, next_is('&') ? 2 : 1);
    } else if (c == '|') {
      take(Tok::Or, next_is('|') ? 2 : 1);
    } else if (c == '!' && next_is('=')) {
      take(Tok::Cmp, 2);
      tok_.cmp = PropExpr::Cmp::Ne;
    } else if (c == '!') {
      take(Tok::Not, 1);
    } else if (c == '<' || c == '>') {
      const bool eq = next_is('=');
      take(Tok::Cmp, eq ? 2 : 1);
      tok_.cmp = c == '<' ? (eq ? PropExpr::Cmp::Le : PropExpr::Cmp::Lt) : (eq ? PropExpr::Cmp::Ge : PropExpr::Cmp::Gt);
    } else if (c == '=' && next_is('=')) {
      take(Tok::Cmp, 2);
      tok_.cmp = PropExpr::Cmp::Eq;
    } else if (c == '=') {
      fail(i, "unexpected '=' (write '==' to compare a count)");
    } else {
      std::string shown = static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f
                              ? "character " + std::to_string(static_cast<unsigned char>(c))
                              : quoted(std::string_view(&c, 1));
      fail(i, "unexpected " + shown);
    }
  }

  bool is_word(std::string_view w) const { return tok_.kind == Tok::Ident && tok_.text == w; }

  // A NAME, CLASS or LOC; `role` names it in messages.
  std::string expect_name(const std::string& role) {
    if (tok_.kind != Tok::Ident) fail(tok_.offset, "expected " + role + ", found " + describe(tok_));
    if (is_prop_keyword(tok_.text))
      fail(tok_.offset, "expected " + role + ", found the keyword " + quoted(tok_.text));
    std::string name(tok_.text);
    advance();
    return name;
  }

  void expect_in(const std::string& before) {
    if (!is_word("in")) fail(tok_.offset, "expected 'in' after " + quoted(before) + ", found " + describe(tok_));
    advance();
  }

  static void append_flat(PropExpr& parent, PropExpr child) {
    if (child.kind == parent.kind) {
      for (PropExpr& c : child.children) parent.children.push_back(std::move(c));
    } else {
      parent.children.push_back(std::move(child));
    }
  }

  PropExpr parse_or(int depth) {
    PropExpr first = parse_and(depth);
    if (tok_.kind != Tok::Or) return first;
    PropExpr e;
    e.kind = PropExpr::Kind::Or;
    append_flat(e, std::move(first));
    while (tok_.kind == Tok::Or) {
      advance();
      append_flat(e, parse_and(depth));
    }
    return e;
  }

  PropExpr parse_and(int depth) {
    PropExpr first = parse_factor(depth);
    if (tok_.kind != Tok::And) return first;
    PropExpr e;
    e.kind = PropExpr::Kind::And;
    append_flat(e, std::move(first));
    while (tok_.kind == Tok::And) {
      advance();
      append_flat(e, parse_factor(depth));
    }
    return e;
  }

  PropExpr parse_factor(int depth) {
    if (depth >= kMaxDepth) fail(tok_.offset, "expression nested too deeply (more than 200 levels)");
    if (tok_.kind == Tok::Not) {
      advance();
      PropExpr e;
      e.kind = PropExpr::Kind::Not;
      e.children.push_back(parse_factor(depth + 1));
      return e;
    }
    if (tok_.kind == Tok::LParen) {
      const std::size_t open = tok_.offset;
      advance();
      PropExpr e = parse_or(depth + 1);
      if (tok_.kind != Tok::RParen) {
        if (tok_.kind == Tok::End) fail(open, "'(' is never closed");
        fail(tok_.offset, "expected ')' or an operator, found " + describe(tok_));
      }
      advance();
      return e;
    }
    return parse_atom();
  }

  PropExpr parse_atom() {
    PropExpr e;
    if (tok_.kind != Tok::Ident) {
      if (tok_.kind == Tok::End) fail(tok_.offset, "expected a proposition, found the end of the expression");
      fail(tok_.offset, "expected a proposition, found " + describe(tok_));
    }
    if (is_word("true") || is_word("false")) {
      e.kind = is_word("true") ? PropExpr::Kind::True : PropExpr::Kind::False;
      advance();
      return e;
    }
    if (is_word("all") || is_word("any") || is_word("count")) {
      const std::string quantifier(tok_.text);
      e.kind = quantifier == "all" ? PropExpr::Kind::All : quantifier == "any" ? PropExpr::Kind::Any : PropExpr::Kind::Count;
      advance();
      e.subject = expect_name("a class after " + quoted(quantifier));
      expect_in(quantifier + " " + e.subject);
      e.location = expect_name("a location name");
      if (e.kind == PropExpr::Kind::Count) {
        if (tok_.kind != Tok::Cmp)
          fail(tok_.offset, "expected a comparison (< <= == != >= >) after 'count " + e.subject + " in " + e.location +
                                "', found " + describe(tok_));
        e.cmp = tok_.cmp;
        advance();
        if (tok_.kind != Tok::Int) fail(tok_.offset, "expected a non-negative integer, found " + describe(tok_));
        if (tok_.text.size() > 7 || std::stoi(std::string(tok_.text)) > kMaxCount)
          fail(tok_.offset, "count " + std::string(tok_.text) + " is too large (at most 1000000)");
        e.count = std::stoi(std::string(tok_.text));
        advance();
      }
      return e;
    }
    if (is_word("in")) fail(tok_.offset, "expected a proposition, found the keyword 'in' (missing the name before it?)");
    e.kind = PropExpr::Kind::In;
    e.subject = std::string(tok_.text);
    advance();
    expect_in(e.subject);
    e.location = expect_name("a location name");
    return e;
  }

  std::string_view text_;
  SourceLocation where_;
  const TextLayout& layout_;
  std::size_t pos_ = 0;
  Token tok_;
};

// Binding strength for printing: Or 1, And 2, Not/atoms 3.
int precedence(const PropExpr& e) {
  switch (e.kind) {
    case PropExpr::Kind::Or:
      return 1;
    case PropExpr::Kind::And:
      return 2;
    default:
      return 3;
  }
}

void print(const PropExpr& e, std::string& out) {
  auto child = [&](const PropExpr& c, int min_prec) {
    if (precedence(c) < min_prec) {
      out += '(';
      print(c, out);
      out += ')';
    } else {
      print(c, out);
    }
  };
  switch (e.kind) {
    case PropExpr::Kind::True:
      out += "true";
      return;
    case PropExpr::Kind::False:
      out += "false";
      return;
    case PropExpr::Kind::In:
      out += e.subject + " in " + e.location;
      return;
    case PropExpr::Kind::All:
      out += "all " + e.subject + " in " + e.location;
      return;
    case PropExpr::Kind::Any:
      out += "any " + e.subject + " in " + e.location;
      return;
    case PropExpr::Kind::Count:
      out += "count " + e.subject + " in " + e.location + " " + to_string(e.cmp) + " " + std::to_string(e.count);
      return;
    case PropExpr::Kind::Not:
      out += '!';
      // "!(o1 in r2)" rather than the equivalent "!o1 in r2", which reads as if ! applied to o1.
      if (!e.children.empty()) {
        const PropExpr& c = e.children[0];
        const bool atom = c.kind == PropExpr::Kind::In || c.kind == PropExpr::Kind::All ||
                          c.kind == PropExpr::Kind::Any || c.kind == PropExpr::Kind::Count;
        child(c, atom ? 4 : 3);
      }
      return;
    case PropExpr::Kind::And:
    case PropExpr::Kind::Or: {
      const char* op = e.kind == PropExpr::Kind::And ? " & " : " | ";
      // A same-kind child (only in hand-built trees) gets parentheses so the
      // text parses back to the same structure.
      const int min_prec = precedence(e) + 1;
      for (std::size_t i = 0; i < e.children.size(); ++i) {
        if (i) out += op;
        child(e.children[i], min_prec);
      }
      return;
    }
  }
}

bool class_matches(const std::string& cls, const Placement::Thing& t) {
  return cls == "object" ? !t.container : t.cls == cls;
}

}  // namespace

bool is_prop_keyword(std::string_view w) {
  return w == "in" || w == "all" || w == "any" || w == "count" || w == "true" || w == "false";
}

PropExpr parse_prop_expr(std::string_view text, const SourceLocation& where, const TextLayout& layout) {
  return Parser(text, where, layout).parse();
}

const char* to_string(PropExpr::Cmp cmp) {
  switch (cmp) {
    case PropExpr::Cmp::Lt:
      return "<";
    case PropExpr::Cmp::Le:
      return "<=";
    case PropExpr::Cmp::Eq:
      return "==";
    case PropExpr::Cmp::Ne:
      return "!=";
    case PropExpr::Cmp::Ge:
      return ">=";
    case PropExpr::Cmp::Gt:
      return ">";
  }
  return "?";
}

std::string to_string(const PropExpr& e) {
  std::string out;
  print(e, out);
  return out;
}

bool evaluate(const PropExpr& e, const Placement& placement) {
  switch (e.kind) {
    case PropExpr::Kind::True:
      return true;
    case PropExpr::Kind::False:
      return false;
    case PropExpr::Kind::In: {
      const std::string* loc = placement.location_of(e.subject);
      return loc != nullptr && *loc == e.location;
    }
    case PropExpr::Kind::All:
      for (const auto& [name, t] : placement.things)
        if (class_matches(e.subject, t) && t.location != e.location) return false;
      return true;
    case PropExpr::Kind::Any:
      for (const auto& [name, t] : placement.things)
        if (class_matches(e.subject, t) && t.location == e.location) return true;
      return false;
    case PropExpr::Kind::Count: {
      std::int64_t n = 0;
      for (const auto& [name, t] : placement.things)
        if (class_matches(e.subject, t) && t.location == e.location) ++n;
      const std::int64_t k = e.count;
      switch (e.cmp) {
        case PropExpr::Cmp::Lt:
          return n < k;
        case PropExpr::Cmp::Le:
          return n <= k;
        case PropExpr::Cmp::Eq:
          return n == k;
        case PropExpr::Cmp::Ne:
          return n != k;
        case PropExpr::Cmp::Ge:
          return n >= k;
        case PropExpr::Cmp::Gt:
          return n > k;
      }
      return false;
    }
    case PropExpr::Kind::Not:
      return !evaluate(e.children.at(0), placement);
    case PropExpr::Kind::And:
      for (const PropExpr& c : e.children)
        if (!evaluate(c, placement)) return false;
      return true;
    case PropExpr::Kind::Or:
      for (const PropExpr& c : e.children)
        if (evaluate(c, placement)) return true;
      return false;
  }
  return false;
}

void collect_names(const PropExpr& e, PropNames& out) {
  switch (e.kind) {
    case PropExpr::Kind::In:
      out.things.insert(e.subject);
      out.locations.insert(e.location);
      break;
    case PropExpr::Kind::All:
    case PropExpr::Kind::Any:
    case PropExpr::Kind::Count:
      out.classes.insert(e.subject);
      out.locations.insert(e.location);
      break;
    default:
      break;
  }
  for (const PropExpr& c : e.children) collect_names(c, out);
}

}  // namespace rtamp::world
