#include "rtamp/ltl/formula.hpp"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <mutex>
#include <unordered_set>

namespace rtamp::ltl {

struct Node {
  Op op;
  std::string name;
  std::vector<Formula> children;
  std::uint64_t id = 0;
  std::size_t structural_hash = 0;
  std::size_t size = 1;
  std::size_t depth = 1;
  bool boolean = true;
  bool eventual = false;
  bool universal = false;
  std::weak_ptr<const Node> self;
};

namespace {

std::size_t structural_hash(Op op, const std::string& name, const std::vector<Formula>& children) {
  std::size_t h = std::hash<std::string>{}(name) * 31 + static_cast<std::size_t>(op);
  for (const Formula& c : children) h = h * 1000003u ^ c.hash();
  return h;
}

// A would-be node, for looking up the table before allocating anything.
struct Probe {
  Op op;
  const std::string* name;
  const std::vector<Formula>* children;
  std::size_t hash;
};

struct NodeHash {
  using is_transparent = void;
  std::size_t operator()(const Node* n) const { return n->structural_hash; }
  std::size_t operator()(const Probe& p) const { return p.hash; }
};
struct NodeEq {
  using is_transparent = void;
  bool operator()(const Node* a, const Node* b) const {
    return a->op == b->op && a->name == b->name && a->children == b->children;
  }
  bool operator()(const Probe& p, const Node* b) const {
    return p.op == b->op && *p.name == b->name && *p.children == b->children;
  }
  bool operator()(const Node* a, const Probe& p) const { return (*this)(p, a); }
};

struct UniqueTable {
  std::mutex mutex;
  std::unordered_set<const Node*, NodeHash, NodeEq> nodes;
  std::uint64_t next_id = 1;
};

UniqueTable& table() {
  static UniqueTable* t = new UniqueTable;  // never destroyed: nodes may outlive static destruction
  return *t;
}

void compute_properties(Node& n) {
  const auto& c = n.children;
  for (const Formula& ch : c) {
    n.size += ch.size();
    n.depth = std::max(n.depth, ch.depth() + 1);
  }
  switch (n.op) {
    case Op::False:
    case Op::True:
      n.boolean = n.eventual = n.universal = true;
      break;
    case Op::Atom:
      n.boolean = true;
      break;
    case Op::Not:
    case Op::Xor:
    case Op::Implies:
    case Op::Equiv:
      n.boolean = std::all_of(c.begin(), c.end(), [](const Formula& f) { return f.is_boolean(); });
      n.eventual = n.universal = false;
      break;
    case Op::And:
    case Op::Or:
      n.boolean = std::all_of(c.begin(), c.end(), [](const Formula& f) { return f.is_boolean(); });
      n.eventual = std::all_of(c.begin(), c.end(), [](const Formula& f) { return f.is_eventual(); });
      n.universal = std::all_of(c.begin(), c.end(), [](const Formula& f) { return f.is_universal(); });
      break;
    case Op::Next:
      n.boolean = false;
      n.eventual = c[0].is_eventual();
      n.universal = c[0].is_universal();
      break;
    case Op::Finally:
      n.boolean = false;
      n.eventual = true;
      n.universal = c[0].is_universal();
      break;
    case Op::Globally:
      n.boolean = false;
      n.eventual = c[0].is_eventual();
      n.universal = true;
      break;
    case Op::Until:  // a U e ≡ e when e is eventual; a U b universal if both are
      n.boolean = false;
      n.eventual = c[1].is_eventual();
      n.universal = c[0].is_universal() && c[1].is_universal();
      break;
    case Op::Release:  // a R u ≡ u when u is universal
      n.boolean = false;
      n.eventual = c[0].is_eventual() && c[1].is_eventual();
      n.universal = c[1].is_universal();
      break;
    case Op::WeakUntil:  // a W b: universal if both universal
      n.boolean = false;
      n.eventual = c[0].is_eventual() && c[1].is_eventual();
      n.universal = c[0].is_universal() && c[1].is_universal();
      break;
    case Op::StrongRelease:  // a M b: eventual if both eventual
      n.boolean = false;
      n.eventual = c[0].is_eventual() && c[1].is_eventual();
      n.universal = c[0].is_universal() && c[1].is_universal();
      break;
  }
}

}  // namespace

const char* op_name(Op op) {
  switch (op) {
    case Op::False: return "0";
    case Op::True: return "1";
    case Op::Atom: return "atom";
    case Op::Not: return "!";
    case Op::Next: return "X";
    case Op::Finally: return "F";
    case Op::Globally: return "G";
    case Op::And: return "&";
    case Op::Or: return "|";
    case Op::Xor: return "xor";
    case Op::Implies: return "->";
    case Op::Equiv: return "<->";
    case Op::Until: return "U";
    case Op::Release: return "R";
    case Op::WeakUntil: return "W";
    case Op::StrongRelease: return "M";
  }
  return "?";
}

bool is_unary(Op op) { return op == Op::Not || op == Op::Next || op == Op::Finally || op == Op::Globally; }
bool is_nary(Op op) { return op == Op::And || op == Op::Or; }
bool is_binary(Op op) {
  switch (op) {
    case Op::Xor: case Op::Implies: case Op::Equiv: case Op::Until:
    case Op::Release: case Op::WeakUntil: case Op::StrongRelease:
      return true;
    default:
      return false;
  }
}

Formula Formula::make(Op op, std::string name, std::vector<Formula> children) {
  const std::size_t h = structural_hash(op, name, children);
  UniqueTable& t = table();
  std::unique_lock lock(t.mutex);
  // Most requests (rewriting passes rebuild existing nodes) hit: look up first.
  if (auto it = t.nodes.find(Probe{op, &name, &children, h}); it != t.nodes.end()) {
    if (auto existing = (*it)->self.lock()) return Formula(std::move(existing));
  }
  lock.unlock();
  auto* fresh = new Node{op, std::move(name), std::move(children)};
  fresh->structural_hash = h;
  lock.lock();
  if (auto it = t.nodes.find(fresh); it != t.nodes.end()) {
    if (auto existing = (*it)->self.lock()) {
      lock.unlock();
      delete fresh;
      return Formula(std::move(existing));
    }
    t.nodes.erase(it);  // expired, its deleter has not run yet: replace it
  }
  fresh->id = t.next_id++;
  compute_properties(*fresh);
  std::shared_ptr<const Node> sp(fresh, [](const Node* n) {
    {
      UniqueTable& tab = table();
      std::lock_guard guard(tab.mutex);
      if (auto it = tab.nodes.find(n); it != tab.nodes.end() && *it == n) tab.nodes.erase(it);
    }
    delete n;  // releases children outside the lock
  });
  fresh->self = sp;
  t.nodes.insert(fresh);
  return Formula(std::move(sp));
}

std::size_t live_formula_nodes() {
  UniqueTable& t = table();
  std::lock_guard guard(t.mutex);
  return t.nodes.size();
}

Formula Formula::tt() {
  static const Formula f = make(Op::True, {}, {});
  return f;
}
Formula Formula::ff() {
  static const Formula f = make(Op::False, {}, {});
  return f;
}
Formula Formula::atom(const std::string& name) { return make(Op::Atom, name, {}); }

Formula Formula::Not(Formula a) {
  switch (a.op()) {
    case Op::True: return ff();
    case Op::False: return tt();
    case Op::Not: return a[0];
    default: return make(Op::Not, {}, {std::move(a)});
  }
}

Formula Formula::X(Formula a) {
  if (a.is_constant()) return a;
  return make(Op::Next, {}, {std::move(a)});
}

Formula Formula::F(Formula a) {
  if (a.is_constant() || a.is(Op::Finally)) return a;
  return make(Op::Finally, {}, {std::move(a)});
}

Formula Formula::G(Formula a) {
  if (a.is_constant() || a.is(Op::Globally)) return a;
  return make(Op::Globally, {}, {std::move(a)});
}

Formula Formula::unary(Op op, Formula a) {
  switch (op) {
    case Op::Not: return Not(std::move(a));
    case Op::Next: return X(std::move(a));
    case Op::Finally: return F(std::move(a));
    case Op::Globally: return G(std::move(a));
    default: assert(false && "not a unary operator"); return a;
  }
}

Formula Formula::nary(Op op, std::vector<Formula> operands) {
  assert(op == Op::And || op == Op::Or);
  const Op absorbing = op == Op::And ? Op::False : Op::True;
  const Op neutral = op == Op::And ? Op::True : Op::False;
  std::vector<Formula> flat;
  flat.reserve(operands.size());
  for (Formula& f : operands) {
    if (f.is(absorbing)) return f;
    if (f.is(neutral)) continue;
    if (f.is(op)) {
      for (const Formula& g : f.children()) flat.push_back(g);
    } else {
      flat.push_back(std::move(f));
    }
  }
  std::sort(flat.begin(), flat.end());
  flat.erase(std::unique(flat.begin(), flat.end()), flat.end());
  if (flat.empty()) return op == Op::And ? tt() : ff();
  if (flat.size() == 1) return flat[0];
  return make(op, {}, std::move(flat));
}

Formula Formula::And(std::vector<Formula> operands) { return nary(Op::And, std::move(operands)); }
Formula Formula::Or(std::vector<Formula> operands) { return nary(Op::Or, std::move(operands)); }

Formula Formula::binary(Op op, Formula a, Formula b) {
  assert(is_binary(op));
  return make(op, {}, {std::move(a), std::move(b)});
}

Formula Formula::with_children(std::vector<Formula> children) const {
  const Op o = op();
  if (is_nary(o)) return nary(o, std::move(children));
  if (is_unary(o)) return unary(o, std::move(children[0]));
  if (is_binary(o)) return binary(o, std::move(children[0]), std::move(children[1]));
  return *this;
}

Op Formula::op() const { return node_->op; }
const std::string& Formula::name() const { return node_->name; }
std::size_t Formula::arity() const { return node_->children.size(); }
const Formula& Formula::operator[](std::size_t i) const { return node_->children[i]; }
const std::vector<Formula>& Formula::children() const { return node_->children; }
std::uint64_t Formula::id() const { return node_ ? node_->id : 0; }
std::size_t Formula::size() const { return node_->size; }
std::size_t Formula::depth() const { return node_->depth; }
bool Formula::is_boolean() const { return node_->boolean; }
bool Formula::is_eventual() const { return node_->eventual; }
bool Formula::is_universal() const { return node_->universal; }

}  // namespace rtamp::ltl
