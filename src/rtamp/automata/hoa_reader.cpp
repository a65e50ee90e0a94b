#include "rtamp/automata/hoa_reader.hpp"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>

#include "rtamp/automata/boolean_guard.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/text_file.hpp"
#include "rtamp/util/utf8.hpp"

namespace rtamp::automata {

namespace {

enum class T {
  Eof, Header, Ident, Bool, Int, String, Alias,
  LBrack, RBrack, LBrace, RBrace, LParen, RParen, Not, And, Or,
  Body, End, Abort
};

struct Tok {
  T kind = T::Eof;
  std::string text;     // identifier/header name (without ':'), unescaped string, alias (without '@')
  std::int64_t ival = 0;
  int line = 1, col = 1;
};

const char* describe(T k) {
  switch (k) {
    case T::Eof: return "end of input";
    case T::Header: return "header name";
    case T::Ident: return "identifier";
    case T::Bool: return "Boolean constant";
    case T::Int: return "integer";
    case T::String: return "string";
    case T::Alias: return "alias";
    case T::LBrack: return "'['";
    case T::RBrack: return "']'";
    case T::LBrace: return "'{'";
    case T::RBrace: return "'}'";
    case T::LParen: return "'('";
    case T::RParen: return "')'";
    case T::Not: return "'!'";
    case T::And: return "'&'";
    case T::Or: return "'|'";
    case T::Body: return "'--BODY--'";
    case T::End: return "'--END--'";
    case T::Abort: return "'--ABORT--'";
  }
  return "token";
}

std::string show(const Tok& t) {
  switch (t.kind) {
    case T::Header: return "'" + t.text + ":'";
    case T::Ident: case T::Bool: return "'" + t.text + "'";
    case T::Int: return "'" + std::to_string(t.ival) + "'";
    case T::Alias: return "'@" + t.text + "'";
    case T::String: return "string \"" + t.text + "\"";
    default: return describe(t.kind);
  }
}

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-'; }

class Lexer {
 public:
  Lexer(std::string_view text, const std::string& file) : s_(text), file_(file) { advance(); }

  const Tok& peek() const { return cur_; }
  Tok next() {
    Tok t = std::move(cur_);
    advance();
    return t;
  }
  [[noreturn]] void fail(const std::string& what, int line, int col) const {
    throw Error(what, SourceLocation{file_, line, col});
  }
  [[noreturn]] void fail(const std::string& what, const Tok& at) const { fail(what, at.line, at.col); }

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
  void skip_space_and_comments() {
    for (;;) {
      while (pos_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[pos_]))) bump();
      if (at(pos_) == '/' && at(pos_ + 1) == '*') {
        const int l = line_, c = col_;
        int depth = 0;
        while (true) {
          if (pos_ >= s_.size()) fail("unterminated comment", l, c);
          if (at(pos_) == '/' && at(pos_ + 1) == '*') {
            ++depth;
            bump();
            bump();
          } else if (at(pos_) == '*' && at(pos_ + 1) == '/') {
            --depth;
            bump();
            bump();
            if (depth == 0) break;
          } else {
            bump();
          }
        }
        continue;
      }
      return;
    }
  }
  void advance() {
    skip_space_and_comments();
    cur_ = Tok{};
    cur_.line = line_;
    cur_.col = col_;
    if (pos_ >= s_.size()) return;
    const char c = s_[pos_];
    auto single = [&](T k) {
      cur_.kind = k;
      bump();
    };
    switch (c) {
      case '[': return single(T::LBrack);
      case ']': return single(T::RBrack);
      case '{': return single(T::LBrace);
      case '}': return single(T::RBrace);
      case '(': return single(T::LParen);
      case ')': return single(T::RParen);
      case '!': return single(T::Not);
      case '&': return single(T::And);
      case '|': return single(T::Or);
      default: break;
    }
    if (c == '"') {
      bump();
      std::string out;
      while (true) {
        if (pos_ >= s_.size()) fail("unterminated string", cur_.line, cur_.col);
        char d = s_[pos_];
        if (d == '"') {
          bump();
          break;
        }
        if (d == '\\') {
          bump();
          if (pos_ >= s_.size()) fail("unterminated string", cur_.line, cur_.col);
          d = s_[pos_];
          if (d == 'n') d = '\n';
        }
        out += d;
        bump();
      }
      if (const std::size_t bad = utf8::first_invalid(out); bad != std::string::npos)
        fail("a string that is not UTF-8 (byte " + std::to_string(bad + 1) + " of the string)", cur_.line, cur_.col);
      cur_.kind = T::String;
      cur_.text = std::move(out);
      return;
    }
    if (std::isdigit(static_cast<unsigned char>(c))) {
      std::int64_t v = 0;
      while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) {
        v = v * 10 + (s_[pos_] - '0');
        if (v >= (std::int64_t{1} << 31)) fail("integer too large (HOA integers are below 2^31)", cur_.line, cur_.col);
        bump();
      }
      cur_.kind = T::Int;
      cur_.ival = v;
      return;
    }
    if (c == '@') {
      bump();
      std::string name;
      while (pos_ < s_.size() && ident_char(s_[pos_])) {
        name += s_[pos_];
        bump();
      }
      if (name.empty()) fail("'@' must be followed by an alias name", cur_.line, cur_.col);
      cur_.kind = T::Alias;
      cur_.text = std::move(name);
      return;
    }
    if (c == '-') {
      for (auto [word, kind] : {std::pair{std::string_view{"--BODY--"}, T::Body},
                                std::pair{std::string_view{"--END--"}, T::End},
                                std::pair{std::string_view{"--ABORT--"}, T::Abort}}) {
        if (s_.substr(pos_, word.size()) == word) {
          for (std::size_t i = 0; i < word.size(); ++i) bump();
          cur_.kind = kind;
          return;
        }
      }
      fail("unexpected '-' (expected --BODY--, --END-- or --ABORT--)", cur_.line, cur_.col);
    }
    if (ident_start(c)) {
      std::string name;
      while (pos_ < s_.size() && ident_char(s_[pos_])) {
        name += s_[pos_];
        bump();
      }
      if (at(pos_) == ':') {
        bump();
        cur_.kind = T::Header;
      } else {
        cur_.kind = (name == "t" || name == "f") ? T::Bool : T::Ident;
      }
      cur_.text = std::move(name);
      return;
    }
    std::string shown = std::isprint(static_cast<unsigned char>(c)) ? std::string(1, c) : "\\x" + [&] {
      const char* hex = "0123456789abcdef";
      const auto u = static_cast<unsigned char>(c);
      return std::string{hex[u >> 4], hex[u & 15]};
    }();
    fail("unexpected character '" + shown + "'", cur_.line, cur_.col);
  }

  std::string_view s_;
  const std::string& file_;
  std::size_t pos_ = 0;
  int line_ = 1, col_ = 1;
  Tok cur_;
};

struct RawEdge {
  std::uint32_t dst;
  std::optional<std::vector<Cube>> label;  // nullopt: implicit
  Marks marks;
  bool has_sig;
  Tok at;
};

struct RawState {
  bool defined = false;
  std::optional<std::vector<Cube>> label;
  Marks marks = 0;
  std::vector<RawEdge> edges;
};

struct Aborted {};

class Parser {
 public:
  Parser(std::string_view text, const std::string& file) : lex_(text, file) {}

  std::vector<Automaton> run() {
    std::vector<Automaton> out;
    while (lex_.peek().kind != T::Eof) {
      try {
        out.push_back(automaton());
      } catch (const Aborted&) {
        // --ABORT--: discard what was read, go on with the next automaton.
      }
    }
    return out;
  }

 private:
  // ---- token helpers
  Tok expect(T k, const char* context) {
    const Tok& t = lex_.peek();
    if (t.kind == T::Abort) {
      lex_.next();
      throw Aborted{};
    }
    if (t.kind != k) lex_.fail(std::string("expected ") + describe(k) + " " + context + ", found " + show(t), t);
    return lex_.next();
  }
  bool accept(T k) {
    if (lex_.peek().kind != k) return false;
    lex_.next();
    return true;
  }
  void check_abort() {
    if (lex_.peek().kind == T::Abort) {
      lex_.next();
      throw Aborted{};
    }
  }

  // ---- label expressions: or := and ('|' and)*, and := un ('&' un)*, un := '!' un | atom
  // And/Or nodes are n-ary (no deep left-leaning chains); aliases are
  // expanded, so their total size per label is bounded by kMaxLabelNodes.
  static constexpr std::size_t kMaxLabelNodes = 100000;
  BoolExpr label_or() {
    BoolExpr e = label_and();
    if (lex_.peek().kind != T::Or) return e;
    BoolExpr n{BoolExpr::Kind::Or, 0, {std::move(e)}};
    while (accept(T::Or)) n.kids.push_back(label_and());
    return n;
  }
  BoolExpr label_and() {
    BoolExpr e = label_unary();
    if (lex_.peek().kind != T::And) return e;
    BoolExpr n{BoolExpr::Kind::And, 0, {std::move(e)}};
    while (accept(T::And)) n.kids.push_back(label_unary());
    return n;
  }
  void count_nodes(std::size_t n, const Tok& at) {
    label_nodes_ += n;
    if (label_nodes_ > kMaxLabelNodes) lex_.fail("label expression too large (aliases expand to too many nodes)", at);
  }
  BoolExpr label_unary() {
    check_abort();
    if (++depth_ > 1000) lex_.fail("label expression nested too deeply", lex_.peek());
    struct Leave {
      int& d;
      ~Leave() { --d; }
    } leave{depth_};
    const Tok& t = lex_.peek();
    count_nodes(1, t);
    switch (t.kind) {
      case T::Not:
        lex_.next();
        return BoolExpr::negate(label_unary());
      case T::LParen: {
        lex_.next();
        BoolExpr e = label_or();
        expect(T::RParen, "to close '('");
        return e;
      }
      case T::Bool: {
        const bool v = t.text == "t";
        lex_.next();
        return BoolExpr::constant(v);
      }
      case T::Int: {
        if (t.ival >= static_cast<std::int64_t>(num_ap_))
          lex_.fail("atomic proposition " + std::to_string(t.ival) + " out of range (AP: " +
                        std::to_string(num_ap_) + ")",
                    t);
        const auto v = static_cast<unsigned>(t.ival);
        lex_.next();
        return BoolExpr::variable(v);
      }
      case T::Alias: {
        auto it = aliases_.find(t.text);
        if (it == aliases_.end()) lex_.fail("undefined alias '@" + t.text + "'", t);
        count_nodes(it->second.second, t);
        lex_.next();
        return it->second.first;
      }
      default:
        lex_.fail("expected a label expression (AP index, alias, t, f, '!' or '('), found " + show(t), t);
    }
  }
  std::vector<Cube> label() {  // after '['
    const Tok start = lex_.peek();
    label_nodes_ = 0;
    BoolExpr e = label_or();
    expect(T::RBrack, "to close the label");
    try {
      return to_dnf(e);
    } catch (const GuardTooLarge&) {
      lex_.fail("label too complex (its disjunctive normal form has too many cubes)", start);
    }
  }

  // ---- acceptance: conjunctions of Inf(i), t, f
  void acc_or() {
    acc_and();
    if (lex_.peek().kind == T::Or)
      lex_.fail("disjunctive acceptance conditions (Rabin, Streett, parity, ...) are not supported; "
                "rtamp reads Büchi and generalized Büchi automata",
                lex_.peek());
  }
  void acc_and() {
    acc_atom();
    while (accept(T::And)) acc_atom();
  }
  void acc_atom() {
    check_abort();
    if (++depth_ > 1000) lex_.fail("acceptance condition nested too deeply", lex_.peek());
    struct Leave {
      int& d;
      ~Leave() { --d; }
    } leave{depth_};
    const Tok t = lex_.next();
    if (t.kind == T::LParen) {
      acc_or();
      expect(T::RParen, "to close '('");
      return;
    }
    if (t.kind == T::Bool) {
      if (t.text == "f") acc_false_ = true;
      return;
    }
    if (t.kind == T::Ident && (t.text == "Inf" || t.text == "Fin")) {
      if (t.text == "Fin")
        lex_.fail("Fin acceptance (co-Büchi, Rabin, Streett, parity) is not supported; "
                  "rtamp reads Büchi and generalized Büchi automata",
                  t);
      expect(T::LParen, "after 'Inf'");
      if (lex_.peek().kind == T::Not) lex_.fail("Inf(!i) acceptance is not supported", lex_.peek());
      const Tok i = expect(T::Int, "in Inf(...)");
      if (i.ival >= declared_sets_)
        lex_.fail("acceptance set " + std::to_string(i.ival) + " out of range (Acceptance: " +
                      std::to_string(declared_sets_) + ")",
                  i);
      if (std::find(inf_sets_.begin(), inf_sets_.end(), i.ival) == inf_sets_.end()) inf_sets_.push_back(i.ival);
      expect(T::RParen, "to close 'Inf('");
      return;
    }
    lex_.fail("expected Inf(i), t, f or '(' in the acceptance condition, found " + show(t), t);
  }

  Marks acc_sig(bool& seen) {  // after '{'
    Marks m = 0;
    while (true) {
      check_abort();
      const Tok t = lex_.next();
      if (t.kind == T::RBrace) break;
      if (t.kind != T::Int) lex_.fail("expected an acceptance set number or '}', found " + show(t), t);
      if (!acc_seen_) lex_.fail("acceptance marks before the Acceptance: header", t);
      if (t.ival >= declared_sets_)
        lex_.fail("acceptance set " + std::to_string(t.ival) + " out of range (Acceptance: " +
                      std::to_string(declared_sets_) + ")",
                  t);
      auto it = std::find(inf_sets_.begin(), inf_sets_.end(), t.ival);
      if (it != inf_sets_.end()) m |= Marks{1} << (it - inf_sets_.begin());
    }
    seen = true;
    return m;
  }

  Automaton automaton() {
    // reset per-automaton state
    num_ap_ = 0;
    aliases_.clear();
    inf_sets_.clear();
    acc_false_ = false;
    acc_seen_ = false;
    declared_sets_ = 0;
    std::optional<std::int64_t> num_states;
    std::vector<std::pair<std::int64_t, Tok>> starts;
    std::vector<std::string> aps;
    std::string name;
    bool trans_acc = false;  // properties: trans-acc

    const Tok hoa = expect(T::Header, "at the start of an automaton (HOA: v1)");
    if (hoa.text != "HOA") lex_.fail("expected 'HOA:' at the start of an automaton, found " + show(hoa), hoa);
    const Tok version = expect(T::Ident, "after 'HOA:'");
    if (version.text != "v1") lex_.fail("unsupported HOA version '" + version.text + "' (rtamp reads v1)", version);

    // ---- header
    while (true) {
      check_abort();
      const Tok& t = lex_.peek();
      if (t.kind == T::Body) {
        lex_.next();
        break;
      }
      if (t.kind != T::Header) lex_.fail("expected a header item or --BODY--, found " + show(t), t);
      const Tok h = lex_.next();
      if (h.text == "States") {
        if (num_states) lex_.fail("States: given twice", h);
        const Tok n = expect(T::Int, "after 'States:'");
        if (n.ival > (1 << 24)) lex_.fail("too many states (at most 2^24)", n);
        num_states = n.ival;
      } else if (h.text == "Start") {
        const Tok s = expect(T::Int, "after 'Start:'");
        if (lex_.peek().kind == T::And)
          lex_.fail("universal branching (Start: with '&') is not supported; rtamp reads non-alternating automata",
                    lex_.peek());
        starts.emplace_back(s.ival, s);
      } else if (h.text == "AP") {
        if (!aps.empty() || num_ap_ > 0) lex_.fail("AP: given twice", h);
        const Tok n = expect(T::Int, "after 'AP:'");
        if (n.ival > static_cast<std::int64_t>(kMaxAtoms))
          lex_.fail("too many atomic propositions (" + std::to_string(n.ival) + "; at most " +
                        std::to_string(kMaxAtoms) + ")",
                    n);
        for (std::int64_t i = 0; i < n.ival; ++i) {
          const Tok s = expect(T::String, "(atomic proposition name; AP: gives their number first)");
          if (std::find(aps.begin(), aps.end(), s.text) != aps.end())
            lex_.fail("atomic proposition \"" + s.text + "\" declared twice", s);
          aps.push_back(s.text);
        }
        if (lex_.peek().kind == T::String)
          lex_.fail("more atomic proposition names than the " + std::to_string(n.ival) + " declared", lex_.peek());
        num_ap_ = static_cast<unsigned>(n.ival);
      } else if (h.text == "Alias") {
        const Tok a = expect(T::Alias, "after 'Alias:'");
        if (aliases_.count(a.text)) lex_.fail("alias '@" + a.text + "' defined twice", a);
        label_nodes_ = 0;
        BoolExpr e = label_or();
        aliases_[a.text] = {std::move(e), label_nodes_};
      } else if (h.text == "Acceptance") {
        if (acc_seen_) lex_.fail("Acceptance: given twice", h);
        const Tok n = expect(T::Int, "after 'Acceptance:'");
        declared_sets_ = n.ival;
        acc_seen_ = true;
        acc_or();
        if (inf_sets_.size() > 32) lex_.fail("more than 32 acceptance sets are not supported", n);
        std::sort(inf_sets_.begin(), inf_sets_.end());
      } else if (h.text == "name") {
        name = expect(T::String, "after 'name:'").text;
      } else if (std::isupper(static_cast<unsigned char>(h.text[0]))) {
        lex_.fail("unsupported header item '" + h.text + ":'", h);
      } else {
        // Lower-case items (acc-name, tool, properties, ...) may be ignored;
        // `properties: trans-acc` keeps one set without marks transition-based.
        while (true) {
          const T k = lex_.peek().kind;
          if (k != T::Ident && k != T::Bool && k != T::Int && k != T::String) break;
          const Tok item = lex_.next();
          trans_acc = trans_acc || (h.text == "properties" && item.kind == T::Ident && item.text == "trans-acc");
        }
      }
    }
    if (!acc_seen_) lex_.fail("missing 'Acceptance:' header item", hoa);

    // ---- body
    std::vector<RawState> states;
    if (num_states) states.reserve(static_cast<std::size_t>(std::min<std::int64_t>(*num_states, 1 << 20)));
    auto check_state = [&](const Tok& t) {
      if (num_states && t.ival >= *num_states)
        lex_.fail("state " + std::to_string(t.ival) + " out of range (States: " + std::to_string(*num_states) + ")",
                  t);
      if (t.ival >= (1 << 24)) lex_.fail("state number too large", t);
      if (static_cast<std::size_t>(t.ival) >= states.size()) states.resize(static_cast<std::size_t>(t.ival) + 1);
    };
    bool edge_sigs = false;
    while (true) {
      check_abort();
      const Tok& t = lex_.peek();
      if (t.kind == T::End) {
        lex_.next();
        break;
      }
      if (t.kind != T::Header || t.text != "State")
        lex_.fail("expected 'State:' or --END--, found " + show(t), t);
      lex_.next();
      std::optional<std::vector<Cube>> slabel;
      if (accept(T::LBrack)) slabel = label();
      const Tok q = expect(T::Int, "(state number) after 'State:'");
      check_state(q);
      const auto qi = static_cast<std::size_t>(q.ival);
      if (states[qi].defined) lex_.fail("state " + std::to_string(q.ival) + " defined twice", q);
      states[qi].defined = true;
      states[qi].label = std::move(slabel);
      accept(T::String);
      bool dummy = false;
      if (accept(T::LBrace)) states[qi].marks = acc_sig(dummy);
      bool labelled = false, unlabelled = false;
      while (true) {
        check_abort();
        const T k = lex_.peek().kind;
        if (k != T::LBrack && k != T::Int) break;
        RawEdge e{0, std::nullopt, 0, false, lex_.peek()};
        if (accept(T::LBrack)) {
          if (states[qi].label) lex_.fail("edge label on a state that has a state label", e.at);
          e.label = label();
          labelled = true;
        } else {
          unlabelled = true;
        }
        if (labelled && unlabelled) lex_.fail("a state mixes labelled and unlabelled edges", e.at);
        const Tok d = expect(T::Int, "(destination state)");
        if (lex_.peek().kind == T::And)
          lex_.fail("universal branching (destination with '&') is not supported; rtamp reads non-alternating automata",
                    lex_.peek());
        check_state(d);
        e.dst = static_cast<std::uint32_t>(d.ival);
        if (accept(T::LBrace)) {
          e.marks = acc_sig(e.has_sig);
          edge_sigs |= e.marks != 0;  // only marks of sets in use count
        }
        states[qi].edges.push_back(std::move(e));
      }
      RawState& s2 = states[qi];
      if (unlabelled && !s2.label) {
        if (num_ap_ > 16) lex_.fail("implicit labels need at most 16 atomic propositions", q);
        const std::size_t need = std::size_t{1} << num_ap_;
        if (s2.edges.size() != need)
          lex_.fail("state " + std::to_string(q.ival) + " has " + std::to_string(s2.edges.size()) +
                        " unlabelled edges; implicit labels need exactly 2^" + std::to_string(num_ap_) + " = " +
                        std::to_string(need),
                    q);
        const Letter all = num_ap_ == 64 ? ~Letter{0} : ((Letter{1} << num_ap_) - 1);
        for (std::size_t i = 0; i < need; ++i) s2.edges[i].label = std::vector<Cube>{Cube{Letter(i), all & ~Letter(i)}};
      }
    }
    for (const auto& [s, tok] : starts) check_state(tok);
    if (num_states && states.size() < static_cast<std::size_t>(*num_states))
      states.resize(static_cast<std::size_t>(*num_states));

    // ---- build
    Automaton a;
    a.name = name;
    a.atoms = aps;
    for (unsigned i = static_cast<unsigned>(aps.size()); i < num_ap_; ++i) a.atoms.push_back("p" + std::to_string(i));
    const auto nsets = static_cast<std::uint32_t>(inf_sets_.size());
    bool state_based;
    if (acc_false_) {
      state_based = true;  // no accepting state at all
    } else if (nsets == 0) {
      state_based = true;  // "t": every run accepts, i.e. every state accepts
    } else {
      state_based = nsets == 1 && !edge_sigs && !trans_acc;
    }
    a.state_based = state_based;
    a.num_sets = state_based ? 1 : nsets;
    for (const RawState& st : states) {
      bool acc = false;
      if (state_based && !acc_false_) acc = nsets == 0 || (st.marks & 1u);
      a.add_state(acc);
    }
    for (std::size_t q = 0; q < states.size(); ++q) {
      const RawState& st = states[q];
      for (const RawEdge& e : st.edges) {
        const std::vector<Cube>& cubes = st.label ? *st.label : *e.label;
        const Marks m = acc_false_ ? 0 : (st.marks | e.marks);
        for (const Cube& c : cubes) a.add_edge(static_cast<std::uint32_t>(q), e.dst, c, m);
      }
    }
    std::vector<std::uint32_t> init;
    for (const auto& [s, tok] : starts)
      if (std::find(init.begin(), init.end(), static_cast<std::uint32_t>(s)) == init.end())
        init.push_back(static_cast<std::uint32_t>(s));
    if (init.size() == 1) {
      a.initial = init[0];
    } else {
      // No start: the empty language. Several: a fresh state with the union of their out-edges.
      const std::uint32_t s = a.add_state(false);
      for (std::uint32_t i : init) {
        const std::vector<Edge> out = a.edges[i];
        for (const Edge& e : out) a.add_edge(s, e.dst, e.guard, e.marks);
      }
      a.initial = s;
    }
    return a;
  }

  Lexer lex_;
  unsigned num_ap_ = 0;
  std::map<std::string, std::pair<BoolExpr, std::size_t>> aliases_;  // expression, node count
  std::size_t label_nodes_ = 0;
  std::vector<std::int64_t> inf_sets_;
  bool acc_false_ = false;
  bool acc_seen_ = false;
  std::int64_t declared_sets_ = 0;
  int depth_ = 0;
};

}  // namespace

std::vector<Automaton> read_hoa(std::string_view text, const std::string& file) {
  return Parser(text, file).run();
}

Automaton read_hoa_one(std::string_view text, const std::string& file) {
  std::vector<Automaton> all = read_hoa(text, file);
  if (all.size() != 1)
    throw Error("expected exactly one automaton, found " + std::to_string(all.size()), SourceLocation{file, 0, 0});
  return std::move(all[0]);
}

std::vector<Automaton> read_hoa_file(const std::string& path) {
  std::string text;
  if (path == "-") {
    text.assign(std::istreambuf_iterator<char>(std::cin), std::istreambuf_iterator<char>());
    return read_hoa(text, "<stdin>");
  }
  return read_hoa(read_text_file(path, "the HOA file"), path);
}

}  // namespace rtamp::automata
