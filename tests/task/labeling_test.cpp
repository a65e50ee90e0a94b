// The compiled labeling against the world layer's reference evaluator
// (world::evaluate over a Placement) on random states and random expressions.
#include "rtamp/task/labeling.hpp"

#include <gtest/gtest.h>

#include <random>

#include "rtamp/world/propositions.hpp"

namespace rtamp::task {
namespace {

using world::PropExpr;

PropExpr random_expr(std::mt19937& rng, const std::vector<std::string>& things, const std::vector<std::string>& locs,
                     const std::vector<std::string>& classes, int depth) {
  PropExpr e;
  const int k = static_cast<int>(rng() % (depth > 0 ? 9 : 6));
  auto pick = [&](const std::vector<std::string>& v) { return v[rng() % v.size()]; };
  switch (k) {
    case 0: e.kind = PropExpr::Kind::In; e.subject = pick(things); e.location = pick(locs); break;
    case 1: e.kind = PropExpr::Kind::All; e.subject = pick(classes); e.location = pick(locs); break;
    case 2: e.kind = PropExpr::Kind::Any; e.subject = pick(classes); e.location = pick(locs); break;
    case 3:
      e.kind = PropExpr::Kind::Count;
      e.subject = pick(classes);
      e.location = pick(locs);
      e.cmp = static_cast<PropExpr::Cmp>(rng() % 6);
      e.count = static_cast<int>(rng() % 4);
      break;
    case 4: e.kind = (rng() & 1) ? PropExpr::Kind::True : PropExpr::Kind::False; break;
    case 5: e.kind = PropExpr::Kind::In; e.subject = "ghost"; e.location = pick(locs); break;
    case 6:
      e.kind = PropExpr::Kind::Not;
      e.children.push_back(random_expr(rng, things, locs, classes, depth - 1));
      break;
    default:
      e.kind = k == 7 ? PropExpr::Kind::And : PropExpr::Kind::Or;
      for (int i = 0; i < 2 + static_cast<int>(rng() % 2); ++i)
        e.children.push_back(random_expr(rng, things, locs, classes, depth - 1));
  }
  return e;
}

TEST(Labeling, AgreesWithReferenceEvaluator) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 60; ++trial) {
    world::Scenario sc;
    const int R = 2 + trial % 4, N = 1 + trial % 9, C = trial % 3;
    for (int i = 0; i < R; ++i) {
      world::Region r;
      r.name = "r" + std::to_string(i + 1);
      r.center = {0, 0.5 * i, 0};
      r.capacity = 100;
      sc.regions.push_back(r);
    }
    for (int i = 0; i < C; ++i) {
      world::Container c;
      c.name = "t" + std::to_string(i + 1);
      c.cls = i % 2 ? "basket" : "tray";
      sc.containers.push_back(c);
    }
    for (int i = 0; i < N; ++i) {
      world::Object o;
      o.name = "o" + std::to_string(i + 1);
      o.cls = i % 3 == 2 ? "cup" : "block";
      sc.objects.push_back(o);
    }
    std::vector<std::string> things, locs{"nowhere"}, classes{"block", "cup", "tray", "basket", "object", "none"};
    for (const auto& o : sc.objects) things.push_back(o.name);
    for (const auto& c : sc.containers) things.push_back(c.name);
    for (const auto& r : sc.regions) locs.push_back(r.name);
    for (const auto& c : sc.containers) locs.push_back(c.name);
    std::vector<std::string> atoms;
    for (int p = 0; p < 8; ++p) {
      world::Proposition prop;
      prop.name = "p" + std::to_string(p);
      prop.expr = random_expr(rng, things, locs, classes, 3);
      sc.propositions.push_back(prop);
      atoms.push_back(prop.name);
    }
    atoms.push_back("o1 in r1");  // parsed by the atom parser
    world::Placement start;
    for (const auto& o : sc.objects) start.set(o.name, "r1", o.cls);
    for (const auto& c : sc.containers) start.set(c.name, "r1", c.cls, true);
    System ts(sc, start);
    Labeling lab(ts, atoms, [](const std::string& a) -> std::optional<PropExpr> { return world::parse_prop_expr(a); });
    ASSERT_TRUE(lab.unknown_atoms().empty());
    for (int k = 0; k < 200; ++k) {
      world::Placement p;
      for (const auto& o : sc.objects) p.set(o.name, locs[1 + rng() % (locs.size() - 1)], o.cls);
      for (const auto& c : sc.containers) p.set(c.name, sc.regions[rng() % sc.regions.size()].name, c.cls, true);
      const State s = ts.encode(p);
      const automata::Letter l = lab.label(s);
      for (std::size_t a = 0; a + 1 < atoms.size(); ++a)
        ASSERT_EQ(((l >> a) & 1) != 0, world::evaluate(sc.propositions[a].expr, p))
            << world::to_string(sc.propositions[a].expr);
      ASSERT_EQ(((l >> (atoms.size() - 1)) & 1) != 0, *p.location_of("o1") == "r1");
    }
  }
}

TEST(Labeling, UnknownAtomsAreReported) {
  world::Scenario sc;
  world::Region r;
  r.name = "r1";
  sc.regions.push_back(r);
  world::Placement p;
  System ts(sc, p);
  Labeling lab(ts, {"nope"});
  ASSERT_EQ(lab.unknown_atoms().size(), 1u);
  EXPECT_EQ(lab.label(ts.initial()), 0u);
}

}  // namespace
}  // namespace rtamp::task
