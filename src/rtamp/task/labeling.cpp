#include "rtamp/task/labeling.hpp"

#include <bit>

namespace rtamp::task {

using Kind = world::PropExpr::Kind;
using Cmp = world::PropExpr::Cmp;

Labeling::Labeling(const System& ts, const std::vector<std::string>& atoms, AtomParser parser) : ts_(&ts) {
  const Layout& lay = ts.layout();
  for (unsigned i = 0; i < lay.per_word; ++i) rep_ |= std::uint64_t{1} << (i * lay.bits);
  high_ = rep_ << (lay.bits - 1);
  const std::uint64_t fields = lay.per_word * lay.bits >= 64 ? ~std::uint64_t{0}
                                                             : ((std::uint64_t{1} << (lay.per_word * lay.bits)) - 1);
  low_ = fields & ~high_;
  for (const auto& atom : atoms) {
    const world::Proposition* p = ts.scenario().find_proposition(atom);
    if (p) {
      roots_.push_back(compile(p->expr));
      continue;
    }
    std::optional<world::PropExpr> parsed;
    if (parser) parsed = parser(atom);
    if (parsed) {
      roots_.push_back(compile(*parsed));
    } else {
      unknown_.push_back(atom);
      world::PropExpr f;
      f.kind = Kind::False;
      roots_.push_back(compile(f));
    }
  }
}

int Labeling::class_index(const std::string& name) {
  for (std::size_t i = 0; i < class_names_.size(); ++i)
    if (class_names_[i] == name) return static_cast<int>(i);
  std::vector<unsigned> members;
  for (unsigned t = 0; t < ts_->num_things(); ++t)
    if (name == "object" ? !ts_->is_container(t) : ts_->thing_class(t) == name) members.push_back(t);
  std::array<std::uint64_t, kStateWords> mask{};
  const Layout& lay = ts_->layout();
  for (unsigned t : members) mask[t / lay.per_word] |= std::uint64_t{1} << (lay.shift(t) + lay.bits - 1);
  class_names_.push_back(name);
  class_things_.push_back(std::move(members));
  class_masks_.push_back(mask);
  return static_cast<int>(class_names_.size() - 1);
}

std::uint32_t Labeling::compile(const world::PropExpr& e) {
  Node n;
  n.kind = e.kind;
  n.cmp = e.cmp;
  n.count = e.count;
  switch (e.kind) {
    case Kind::In:
      n.thing = ts_->find_thing(e.subject);
      n.loc = ts_->find_location(e.location);
      break;
    case Kind::All:
    case Kind::Any:
    case Kind::Count:
      n.cls = class_index(e.subject);
      n.loc = ts_->find_location(e.location);
      break;
    default:
      break;
  }
  for (const auto& c : e.children) n.children.push_back(compile(c));
  nodes_.push_back(std::move(n));
  return static_cast<std::uint32_t>(nodes_.size() - 1);
}

int Labeling::count(const State& s, int cls, int loc) const {
  if (cls < 0 || loc < 0) return 0;
  const auto& mask = class_masks_[static_cast<unsigned>(cls)];
  const std::uint64_t pattern = rep_ * static_cast<std::uint64_t>(loc);
  int total = 0;
  for (unsigned w = 0; w < ts_->layout().words; ++w) {
    if (!mask[w]) continue;
    const std::uint64_t x = s.words[w] ^ pattern;
    const std::uint64_t nonzero = (((x & low_) + low_) | x) & high_;
    total += std::popcount(~nonzero & mask[w]);
  }
  return total;
}

bool Labeling::eval(std::uint32_t id, const State& s) const {
  const Node& n = nodes_[id];
  switch (n.kind) {
    case Kind::True:
      return true;
    case Kind::False:
      return false;
    case Kind::In:
      return n.thing >= 0 && n.loc >= 0 && ts_->location(s, static_cast<unsigned>(n.thing)) == static_cast<std::uint32_t>(n.loc);
    case Kind::All: {
      const int total = n.cls < 0 ? 0 : static_cast<int>(class_things_[static_cast<unsigned>(n.cls)].size());
      return count(s, n.cls, n.loc) == total;
    }
    case Kind::Any:
      return count(s, n.cls, n.loc) > 0;
    case Kind::Count: {
      const int c = count(s, n.cls, n.loc);
      switch (n.cmp) {
        case Cmp::Lt: return c < n.count;
        case Cmp::Le: return c <= n.count;
        case Cmp::Eq: return c == n.count;
        case Cmp::Ne: return c != n.count;
        case Cmp::Ge: return c >= n.count;
        case Cmp::Gt: return c > n.count;
      }
      return false;
    }
    case Kind::Not:
      return !eval(n.children[0], s);
    case Kind::And:
      for (auto c : n.children)
        if (!eval(c, s)) return false;
      return true;
    case Kind::Or:
      for (auto c : n.children)
        if (eval(c, s)) return true;
      return false;
  }
  return false;
}

std::vector<bool> Labeling::named_things() const {
  std::vector<bool> named(ts_->num_things(), false);
  for (const Node& n : nodes_)
    if (n.kind == Kind::In && n.thing >= 0) named[static_cast<unsigned>(n.thing)] = true;
  return named;
}

std::vector<std::vector<unsigned>> Labeling::symmetry_groups() const {
  const auto named = named_things();
  std::vector<std::vector<unsigned>> groups;
  for (unsigned t = 0; t < ts_->num_objects(); ++t) {
    if (named[t]) continue;
    // Same class and the same moves (footprint rules, forbidden moves).
    std::size_t g = 0;
    while (g < groups.size() &&
           !(ts_->thing_class(groups[g][0]) == ts_->thing_class(t) && ts_->same_moves(groups[g][0], t)))
      ++g;
    if (g == groups.size()) groups.emplace_back();
    groups[g].push_back(t);
  }
  return groups;
}

std::vector<std::vector<unsigned>> Labeling::container_groups() const {
  auto named = named_things();
  for (const Node& n : nodes_)
    if (n.loc >= 0 && ts_->is_container_location(static_cast<unsigned>(n.loc)))
      named[ts_->thing_of_location(static_cast<unsigned>(n.loc))] = true;
  std::vector<std::vector<unsigned>> groups;
  for (unsigned t = ts_->num_objects(); t < ts_->num_things(); ++t) {
    if (named[t]) continue;
    std::size_t g = 0;
    while (g < groups.size() &&
           !(ts_->thing_class(groups[g][0]) == ts_->thing_class(t) && ts_->same_containers(groups[g][0], t)))
      ++g;
    if (g == groups.size()) groups.emplace_back();
    groups[g].push_back(t);
  }
  return groups;
}

automata::Letter Labeling::label(const State& s) const {
  automata::Letter l = 0;
  for (std::size_t i = 0; i < roots_.size(); ++i)
    if (eval(roots_[i], s)) l |= automata::Letter{1} << i;
  return l;
}

}  // namespace rtamp::task
