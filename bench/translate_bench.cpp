// LTL -> Büchi translation benchmarks: each of the 55 Dwyer patterns
// (tests/data/dac-patterns.ltl, one benchmark per pattern, BA and TGBA), the
// robot formulas, and random formulas (size 15, 4 atoms). Counters: states
// and edges of the result (edges = guard cubes; pairs = distinct src->dst;
// sets = acceptance sets).
#include <benchmark/benchmark.h>

#include <fstream>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp_source_dir.hpp"

namespace {

using namespace rtamp;

std::vector<ltl::Formula> load(const char* name) {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/" + name);
  std::vector<ltl::Formula> out;
  std::string line;
  while (std::getline(in, line)) {
    const auto p = line.find_first_not_of(" \t");
    if (p == std::string::npos || line[p] == '#') continue;
    out.push_back(ltl::parse(line));
  }
  return out;
}

const std::vector<ltl::Formula>& dwyer() {
  static const std::vector<ltl::Formula> f = load("dac-patterns.ltl");
  return f;
}

std::size_t pairs(const automata::Automaton& a) {
  std::size_t n = 0;
  for (const auto& out : a.edges) {
    std::set<std::uint32_t> d;
    for (const auto& e : out) d.insert(e.dst);
    n += d.size();
  }
  return n;
}

void report(benchmark::State& state, const automata::Automaton& a) {
  state.counters["states"] = a.num_states();
  state.counters["edges"] = static_cast<double>(a.num_edges());
  state.counters["pairs"] = static_cast<double>(pairs(a));
  state.counters["sets"] = a.num_sets;
}

void BM_TranslateDwyerBA(benchmark::State& state) {
  const ltl::Formula& f = dwyer().at(static_cast<std::size_t>(state.range(0)));
  automata::Automaton a;
  for (auto _ : state) {
    a = automata::translate(f);
    benchmark::DoNotOptimize(a);
  }
  report(state, a);
}
BENCHMARK(BM_TranslateDwyerBA)->DenseRange(0, 54);

void BM_TranslateDwyerTGBA(benchmark::State& state) {
  const ltl::Formula& f = dwyer().at(static_cast<std::size_t>(state.range(0)));
  automata::TranslateOptions o;
  o.state_based = false;
  automata::Automaton a;
  for (auto _ : state) {
    a = automata::translate(f, o);
    benchmark::DoNotOptimize(a);
  }
  report(state, a);
}
BENCHMARK(BM_TranslateDwyerTGBA)->DenseRange(0, 54);

// All 55 patterns per iteration; totals as counters.
void BM_TranslateDwyerAll(benchmark::State& state) {
  std::size_t states = 0, edges = 0, prs = 0;
  for (auto _ : state) {
    states = edges = prs = 0;
    for (const ltl::Formula& f : dwyer()) {
      const automata::Automaton a = automata::translate(f);
      states += a.num_states();
      edges += a.num_edges();
      prs += pairs(a);
    }
  }
  state.counters["states"] = static_cast<double>(states);
  state.counters["edges"] = static_cast<double>(edges);
  state.counters["pairs"] = static_cast<double>(prs);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * dwyer().size()));
}
BENCHMARK(BM_TranslateDwyerAll);

void BM_TranslateRobot(benchmark::State& state) {
  static const std::vector<ltl::Formula> robot = load("robot-patterns.ltl");
  std::size_t states = 0;
  for (auto _ : state) {
    states = 0;
    for (const ltl::Formula& f : robot) states += automata::translate(f).num_states();
  }
  state.counters["states"] = static_cast<double>(states);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * robot.size()));
}
BENCHMARK(BM_TranslateRobot);

// Random formulas of tree size 15 over 4 atoms (a fixed set of 1000).
void BM_TranslateRandom(benchmark::State& state) {
  static const std::vector<ltl::Formula> formulas = [] {
    std::mt19937_64 rng(42);
    ltl::RandomFormulaOptions o;
    o.atoms = {"a", "b", "c", "d"};
    o.size = 15;
    std::vector<ltl::Formula> v;
    for (int i = 0; i < 1000; ++i) v.push_back(ltl::random_formula(rng, o));
    return v;
  }();
  automata::TranslateOptions o;
  o.state_based = state.range(0) != 0;
  std::size_t i = 0, states = 0, edges = 0, n = 0;
  for (auto _ : state) {
    const automata::Automaton a = automata::translate(formulas[i], o);
    states += a.num_states();
    edges += a.num_edges();
    ++n;
    i = (i + 1) % formulas.size();
  }
  state.counters["avg_states"] = n ? static_cast<double>(states) / static_cast<double>(n) : 0.0;
  state.counters["avg_edges"] = n ? static_cast<double>(edges) / static_cast<double>(n) : 0.0;
}
BENCHMARK(BM_TranslateRandom)->Arg(1)->Arg(0);

}  // namespace

BENCHMARK_MAIN();
