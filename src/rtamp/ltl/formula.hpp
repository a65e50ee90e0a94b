// LTL formula AST with hash-consing (paper Section II: the specification φ).
//
// A Formula is a small handle to an immutable, shared node. Nodes are
// hash-consed: two structurally equal formulas are the same node, so equality
// and hashing are pointer operations. Nodes are reference counted and leave the
// unique table when the last handle goes away. Thread safe (one global lock on
// node creation and destruction).
//
// Constructors apply only the trivial, always-valid identities (as Spot does):
//   !!a = a, !true = false; X/F/G of true/false; F F a = F a; G G a = G a;
//   And/Or are n-ary, flattened, sorted by node id, duplicate-free, with
//   true/false absorbed. Everything heavier lives in simplify.hpp.
// Invariant: children of And/Or are sorted by id(), so the same set of
// operands always gives the same node.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace rtamp::ltl {

enum class Op : std::uint8_t {
  False,
  True,
  Atom,
  Not,
  Next,           // X
  Finally,        // F
  Globally,       // G
  And,            // n-ary
  Or,             // n-ary
  Xor,            // binary
  Implies,        // binary
  Equiv,          // binary
  Until,          // a U b  (strong)
  Release,        // a R b  (weak)
  WeakUntil,      // a W b
  StrongRelease,  // a M b
};

const char* op_name(Op op);  // "U", "&", "F", ...
bool is_unary(Op op);
bool is_binary(Op op);       // Xor, Implies, Equiv, U, R, W, M
bool is_nary(Op op);         // And, Or

struct Node;

class Formula {
 public:
  Formula() = default;  // the null formula; only valid as a placeholder

  // Constants and atoms.
  static Formula tt();
  static Formula ff();
  static Formula atom(const std::string& name);

  // Operators.
  static Formula Not(Formula a);
  static Formula X(Formula a);
  static Formula F(Formula a);
  static Formula G(Formula a);
  static Formula And(std::vector<Formula> operands);
  static Formula Or(std::vector<Formula> operands);
  static Formula And(Formula a, Formula b) { return And(std::vector<Formula>{a, b}); }
  static Formula Or(Formula a, Formula b) { return Or(std::vector<Formula>{a, b}); }
  static Formula Xor(Formula a, Formula b) { return binary(Op::Xor, a, b); }
  static Formula Implies(Formula a, Formula b) { return binary(Op::Implies, a, b); }
  static Formula Equiv(Formula a, Formula b) { return binary(Op::Equiv, a, b); }
  static Formula U(Formula a, Formula b) { return binary(Op::Until, a, b); }
  static Formula R(Formula a, Formula b) { return binary(Op::Release, a, b); }
  static Formula W(Formula a, Formula b) { return binary(Op::WeakUntil, a, b); }
  static Formula M(Formula a, Formula b) { return binary(Op::StrongRelease, a, b); }
  static Formula unary(Op op, Formula a);
  static Formula binary(Op op, Formula a, Formula b);
  static Formula nary(Op op, std::vector<Formula> operands);
  // Same operator, new children (for rewriting passes).
  Formula with_children(std::vector<Formula> children) const;

  bool is_null() const { return !node_; }
  explicit operator bool() const { return node_ != nullptr; }

  Op op() const;
  bool is(Op o) const { return op() == o; }
  bool is_constant() const { return op() == Op::True || op() == Op::False; }
  const std::string& name() const;                 // atom name; empty otherwise
  std::size_t arity() const;                       // number of children
  const Formula& operator[](std::size_t i) const;  // i-th child
  const std::vector<Formula>& children() const;

  // Unique among live nodes, increasing with creation; the canonical order.
  std::uint64_t id() const;
  std::size_t hash() const { return std::hash<const void*>{}(node_.get()); }
  std::size_t size() const;   // number of nodes in the tree (shared nodes counted again)
  std::size_t depth() const;  // 1 for an atom

  // Syntactic classes, computed at construction.
  bool is_boolean() const;    // no temporal operator
  bool is_eventual() const;   // pure eventuality: f ≡ F f (syntactic)
  bool is_universal() const;  // purely universal: f ≡ G f (syntactic)

  friend bool operator==(const Formula& a, const Formula& b) { return a.node_ == b.node_; }
  friend bool operator!=(const Formula& a, const Formula& b) { return a.node_ != b.node_; }
  // Total order by id (stable within a process run).
  friend bool operator<(const Formula& a, const Formula& b) { return a.id() < b.id(); }

 private:
  explicit Formula(std::shared_ptr<const Node> n) : node_(std::move(n)) {}
  static Formula make(Op op, std::string name, std::vector<Formula> children);
  std::shared_ptr<const Node> node_;
  friend struct Node;
};

// Number of distinct live nodes (for tests of the unique table).
std::size_t live_formula_nodes();

}  // namespace rtamp::ltl

template <>
struct std::hash<rtamp::ltl::Formula> {
  std::size_t operator()(const rtamp::ltl::Formula& f) const noexcept { return f.hash(); }
};
