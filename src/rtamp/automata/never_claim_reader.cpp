#include "rtamp/automata/never_claim_reader.hpp"

#include <cctype>
#include <map>
#include <vector>

#include "rtamp/automata/boolean_guard.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::automata {

namespace {

enum class T { Eof, Ident, Label, Int, LBrace, RBrace, LParen, RParen, Semi, Options, Arrow, Not, And, Or };

struct Tok {
  T kind = T::Eof;
  std::string text;
  int line = 1, col = 1;
};

std::string show(const Tok& t) {
  switch (t.kind) {
    case T::Eof: return "end of input";
    case T::Ident: case T::Int: return "'" + t.text + "'";
    case T::Label: return "label '" + t.text + ":'";
    default: return "'" + t.text + "'";
  }
}

class Lexer {
 public:
  Lexer(std::string_view s, const std::string& file) : s_(s), file_(file) { advance(); }
  const Tok& peek() const { return cur_; }
  Tok next() {
    Tok t = std::move(cur_);
    advance();
    return t;
  }
  [[noreturn]] void fail(const std::string& what, const Tok& at) const {
    throw Error(what, SourceLocation{file_, at.line, at.col});
  }

 private:
  char at(std::size_t i) const { return i < s_.size() ? s_[i] : '\0'; }
  void bump() {
    if (s_[pos_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++pos_;
  }
  void skip() {
    for (;;) {
      while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) bump();
      if (at(pos_) == '/' && at(pos_ + 1) == '*') {
        Tok start;
        start.line = line_;
        start.col = col_;
        bump();
        bump();
        while (!(at(pos_) == '*' && at(pos_ + 1) == '/')) {
          if (pos_ >= s_.size()) fail("unterminated comment", start);
          bump();
        }
        bump();
        bump();
        continue;
      }
      if (at(pos_) == '/' && at(pos_ + 1) == '/') {
        while (pos_ < s_.size() && s_[pos_] != '\n') bump();
        continue;
      }
      return;
    }
  }
  void advance() {
    skip();
    cur_ = Tok{};
    cur_.line = line_;
    cur_.col = col_;
    if (pos_ >= s_.size()) return;
    const char c = s_[pos_];
    auto take = [&](T k, int n) {
      cur_.kind = k;
      cur_.text = std::string(s_.substr(pos_, static_cast<std::size_t>(n)));
      for (int i = 0; i < n; ++i) bump();
    };
    switch (c) {
      case '{': return take(T::LBrace, 1);
      case '}': return take(T::RBrace, 1);
      case '(': return take(T::LParen, 1);
      case ')': return take(T::RParen, 1);
      case ';': return take(T::Semi, 1);
      case '!': return take(T::Not, 1);
      default: break;
    }
    if (c == ':' && at(pos_ + 1) == ':') return take(T::Options, 2);
    if (c == '-' && at(pos_ + 1) == '>') return take(T::Arrow, 2);
    if (c == '&' && at(pos_ + 1) == '&') return take(T::And, 2);
    if (c == '|' && at(pos_ + 1) == '|') return take(T::Or, 2);
    if (std::isdigit(static_cast<unsigned char>(c))) {
      std::size_t n = 0;
      while (std::isdigit(static_cast<unsigned char>(at(pos_ + n)))) ++n;
      return take(T::Int, static_cast<int>(n));
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t n = 0;
      while (std::isalnum(static_cast<unsigned char>(at(pos_ + n))) || at(pos_ + n) == '_') ++n;
      take(T::Ident, static_cast<int>(n));
      // A label is an identifier followed by ':' (but not '::').
      std::size_t k = pos_;
      while (k < s_.size() && (s_[k] == ' ' || s_[k] == '\t')) ++k;
      if (at(k) == ':' && at(k + 1) != ':') {
        while (pos_ <= k) bump();
        cur_.kind = T::Label;
      }
      return;
    }
    Tok bad = cur_;
    bad.text = std::string(1, c);
    fail("unexpected character '" + bad.text + "' in never claim", bad);
  }

  std::string_view s_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1, col_ = 1;
  Tok cur_;
};

// Where an option leads.
enum class Target { Label, Next, Self, End };

struct Option {
  BoolExpr guard;
  Target target = Target::Next;
  Tok label;  // for Target::Label
  Tok at;
};

struct Stmt {
  std::vector<std::string> labels;
  bool is_skip = false;
  std::vector<Option> options;
  Tok at;
};

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : lex_(text, file) {}

  Automaton run() {
    const Tok nev = lex_.next();
    if (nev.kind != T::Ident || nev.text != "never") lex_.fail("expected 'never' at the start of a never claim, found " + show(nev), nev);
    if (lex_.peek().kind == T::Ident) lex_.next();  // optional claim name
    expect(T::LBrace, "'{' after 'never'");
    std::vector<Stmt> stmts;
    std::vector<std::string> pending;
    while (lex_.peek().kind != T::RBrace) {
      const Tok& t = lex_.peek();
      if (t.kind == T::Eof) lex_.fail("missing '}' at the end of the never claim", t);
      if (t.kind == T::Label) {
        pending.push_back(lex_.next().text);
        continue;
      }
      if (t.kind == T::Semi) {
        lex_.next();
        continue;
      }
      Stmt s = statement();
      s.labels = std::move(pending);
      pending.clear();
      stmts.push_back(std::move(s));
    }
    const Tok close = lex_.next();
    if (!pending.empty()) {
      // Labels at the very end denote the end of the claim.
      Stmt s;
      s.labels = std::move(pending);
      s.is_skip = true;  // reaching the end: accept everything
      s.at = close;
      Option o;
      o.guard = BoolExpr::constant(true);
      o.target = Target::End;
      s.options.push_back(o);
      stmts.push_back(std::move(s));
    }
    if (lex_.peek().kind != T::Eof) lex_.fail("unexpected " + show(lex_.peek()) + " after the never claim", lex_.peek());
    return build(stmts);
  }

 private:
  Tok expect(T k, const char* what) {
    const Tok& t = lex_.peek();
    if (t.kind != k) lex_.fail(std::string("expected ") + what + ", found " + show(t), t);
    return lex_.next();
  }
  bool is_word(const char* w) const { return lex_.peek().kind == T::Ident && lex_.peek().text == w; }

  Stmt statement() {
    Stmt s;
    s.at = lex_.peek();
    if (is_word("if") || is_word("do")) {
      const bool loop = is_word("do");
      lex_.next();
      while (lex_.peek().kind == T::Options) {
        lex_.next();
        s.options.push_back(option(loop));
      }
      if (s.options.empty()) lex_.fail("expected '::' options after 'if' / 'do'", lex_.peek());
      const Tok end = lex_.next();
      if (end.kind != T::Ident || end.text != (loop ? "od" : "fi"))
        lex_.fail(std::string("expected '") + (loop ? "od" : "fi") + "' or another '::' option, found " + show(end), end);
      return s;
    }
    if (is_word("skip")) {
      lex_.next();
      s.is_skip = true;
      Option o;
      o.guard = BoolExpr::constant(true);
      o.at = s.at;
      s.options.push_back(o);
      return s;
    }
    if (is_word("goto")) lex_.fail("a bare 'goto' statement is not supported in never claims here", s.at);
    // An expression statement: a guard, then fall through.
    Option o;
    o.at = s.at;
    o.guard = expr_or();
    s.options.push_back(std::move(o));
    return s;
  }

  Option option(bool loop) {
    Option o;
    o.at = lex_.peek();
    if (is_word("atomic")) {
      // atomic { guard -> assert(!(guard)) }: matched, accept everything after.
      lex_.next();
      expect(T::LBrace, "'{' after 'atomic'");
      o.guard = expr_or();
      expect(T::Arrow, "'->' in atomic { guard -> assert(...) }");
      const Tok a = lex_.next();
      if (a.kind != T::Ident || a.text != "assert") lex_.fail("expected 'assert' in atomic { guard -> assert(...) }, found " + show(a), a);
      expect(T::LParen, "'(' after 'assert'");
      (void)expr_or();
      expect(T::RParen, "')' closing assert(...)");
      if (lex_.peek().kind == T::Semi) lex_.next();
      expect(T::RBrace, "'}' closing atomic { ... }");
      o.target = Target::End;
      if (lex_.peek().kind == T::Semi) lex_.next();
      return o;
    }
    o.guard = expr_or();
    o.target = loop ? Target::Self : Target::Next;
    if (lex_.peek().kind == T::Arrow || lex_.peek().kind == T::Semi) {
      lex_.next();
      if (is_word("goto")) {
        lex_.next();
        const Tok l = lex_.next();
        if (l.kind != T::Ident) lex_.fail("expected a label after 'goto', found " + show(l), l);
        o.label = l;
        o.target = Target::Label;
      } else if (is_word("skip")) {
        lex_.next();
      } else if (is_word("break")) {
        lex_.fail("'break' is not supported in never claims here", lex_.peek());
      }
    }
    if (lex_.peek().kind == T::Semi) lex_.next();
    return o;
  }

  BoolExpr expr_or() {
    BoolExpr e = expr_and();
    if (lex_.peek().kind != T::Or) return e;
    BoolExpr n{BoolExpr::Kind::Or, 0, {std::move(e)}};
    while (lex_.peek().kind == T::Or) {
      lex_.next();
      n.kids.push_back(expr_and());
    }
    return n;
  }
  BoolExpr expr_and() {
    BoolExpr e = expr_unary();
    if (lex_.peek().kind != T::And) return e;
    BoolExpr n{BoolExpr::Kind::And, 0, {std::move(e)}};
    while (lex_.peek().kind == T::And) {
      lex_.next();
      n.kids.push_back(expr_unary());
    }
    return n;
  }
  BoolExpr expr_unary() {
    if (++depth_ > 1000) lex_.fail("guard nested too deeply", lex_.peek());
    struct Leave {
      int& d;
      ~Leave() { --d; }
    } leave{depth_};
    const Tok t = lex_.next();
    switch (t.kind) {
      case T::Not:
        return BoolExpr::negate(expr_unary());
      case T::LParen: {
        BoolExpr e = expr_or();
        expect(T::RParen, "')'");
        return e;
      }
      case T::Int:
        if (t.text == "0") return BoolExpr::constant(false);
        if (t.text == "1") return BoolExpr::constant(true);
        lex_.fail("integer " + t.text + " in a guard (only 0 and 1 are Boolean)", t);
      case T::Ident: {
        if (t.text == "true") return BoolExpr::constant(true);
        if (t.text == "false") return BoolExpr::constant(false);
        static const char* const keywords[] = {"if", "fi", "do", "od", "goto", "skip", "atomic", "assert", "never"};
        for (const char* k : keywords)
          if (t.text == k) lex_.fail("expected a guard, found keyword '" + t.text + "'", t);
        if (a_.find_atom(t.text) < 0 && a_.atoms.size() >= kMaxAtoms)
          lex_.fail("too many atomic propositions (at most " + std::to_string(kMaxAtoms) + ")", t);
        return BoolExpr::variable(a_.atom_index(t.text));
      }
      default:
        lex_.fail("expected a guard (atom, 0, 1, true, false, '!' or '('), found " + show(t), t);
    }
  }

  Automaton build(const std::vector<Stmt>& stmts) {
    Automaton& a = a_;
    a.state_based = true;
    a.num_sets = 1;
    std::map<std::string, std::uint32_t> where;
    for (std::size_t i = 0; i < stmts.size(); ++i) {
      bool acc = false;
      for (const auto& l : stmts[i].labels) {
        if (!where.emplace(l, static_cast<std::uint32_t>(i)).second)
          lex_.fail("label '" + l + "' defined twice", stmts[i].at);
        acc |= l.rfind("accept", 0) == 0;
      }
      a.add_state(acc);
    }
    // The end of the claim accepts every continuation. A final `skip` is that
    // already: make it accepting with a true self-loop and use it as the end.
    std::int64_t end = -1;
    if (!stmts.empty() && stmts.back().is_skip) {
      end = static_cast<std::int64_t>(stmts.size() - 1);
      a.state_accepting[stmts.size() - 1] = true;
    }
    auto end_state = [&]() -> std::uint32_t {
      if (end < 0) {
        end = a.add_state(true);
        a.add_edge(static_cast<std::uint32_t>(end), static_cast<std::uint32_t>(end), Cube{});
      }
      return static_cast<std::uint32_t>(end);
    };
    for (std::size_t i = 0; i < stmts.size(); ++i) {
      const auto q = static_cast<std::uint32_t>(i);
      if (static_cast<std::int64_t>(i) == end) {
        a.add_edge(q, q, Cube{});
        continue;
      }
      for (const Option& o : stmts[i].options) {
        std::vector<Cube> cubes;
        try {
          cubes = to_dnf(o.guard);
        } catch (const GuardTooLarge&) {
          lex_.fail("guard too complex (its disjunctive normal form has too many cubes)", o.at);
        }
        if (cubes.empty()) continue;
        std::uint32_t dst = q;
        switch (o.target) {
          case Target::Self: dst = q; break;
          case Target::Next: dst = i + 1 < stmts.size() ? q + 1 : end_state(); break;
          case Target::End: dst = end_state(); break;
          case Target::Label: {
            auto it = where.find(o.label.text);
            if (it == where.end()) lex_.fail("undefined label '" + o.label.text + "'", o.label);
            dst = it->second;
            break;
          }
        }
        for (const Cube& c : cubes) a.add_edge(q, dst, c);
      }
    }
    if (stmts.empty()) end_state();
    a.initial = 0;
    return std::move(a);
  }

  Lexer lex_;
  Automaton a_;
  int depth_ = 0;
};

}  // namespace

Automaton read_never_claim(std::string_view text, const std::string& file) { return Parser(text, file).run(); }

}  // namespace rtamp::automata
