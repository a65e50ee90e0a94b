// spin vs rtamp on the 55 Dwyer patterns (tests/data/dac-patterns.ltl), in
// the same run: BM_SpinDwyer/i runs `spin -f` as a process per iteration
// (wall time, including process start; 30 s limit) and counts the states and
// edges of its never claim as read by never_claim_reader; BM_OursDwyer/i
// translates the same formula in-process (BA; CPU time). BM_SpinStartup is `spin -f p`,
// the per-process floor. Counters: states, edges (guard cubes), pairs
// (distinct source->destination). Skipped (with a message) without spin.
// scripts/compare-spin turns the JSON output into the tables of
// docs/benchmarks.md.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp_source_dir.hpp"

namespace {

using namespace rtamp;

const std::vector<ltl::Formula>& dwyer() {
  static const std::vector<ltl::Formula> all = [] {
    std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/dac-patterns.ltl");
    std::vector<ltl::Formula> out;
    std::string line;
    while (std::getline(in, line)) {
      const auto p = line.find_first_not_of(" \t");
      if (p == std::string::npos || line[p] == '#') continue;
      out.push_back(ltl::parse(line));
    }
    return out;
  }();
  return all;
}

bool have_spin() {
  static const bool yes = std::system("command -v spin >/dev/null 2>&1 && command -v timeout >/dev/null 2>&1") == 0;
  return yes;
}

// Runs spin -f; returns false on failure or timeout.
bool run_spin(const std::string& spin_text, std::string& claim) {
  const std::string cmd = "timeout 30 spin -f '" + spin_text + "' 2>/dev/null";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return false;
  claim.clear();
  std::array<char, 1 << 14> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) claim.append(buf.data(), n);
  return ::pclose(p) == 0 && claim.rfind("never", 0) == 0;
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
}

void BM_SpinStartup(benchmark::State& state) {
  if (!have_spin()) {
    state.SkipWithError("spin is not installed");
    return;
  }
  std::string claim;
  for (auto _ : state) {
    if (!run_spin("p", claim)) {
      state.SkipWithError("spin -f p failed");
      break;
    }
  }
}
BENCHMARK(BM_SpinStartup)->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(20);

void BM_SpinDwyer(benchmark::State& state) {
  if (!have_spin()) {
    state.SkipWithError("spin is not installed");
    return;
  }
  const ltl::Formula& f = dwyer().at(static_cast<std::size_t>(state.range(0)));
  std::map<std::string, std::string> renamed;
  const std::string text = ltl::to_spin_string(f, &renamed);
  if (text.find('X') != std::string::npos) {
    // Debian's spin 6.5 is built without the next-time operator.
    state.SkipWithError("no X: this spin build rejects the next-time operator");
    return;
  }
  std::string claim;
  for (auto _ : state) {
    if (!run_spin(text, claim)) {
      state.SkipWithError("spin failed or took more than 30 s");
      break;
    }
  }
  if (!claim.empty() && claim.rfind("never", 0) == 0) report(state, automata::read_never_claim(claim));
}
BENCHMARK(BM_SpinDwyer)->DenseRange(0, 54)->UseRealTime()->Unit(benchmark::kMillisecond)->Iterations(3);

void BM_OursDwyer(benchmark::State& state) {
  const ltl::Formula& f = dwyer().at(static_cast<std::size_t>(state.range(0)));
  automata::Automaton a;
  for (auto _ : state) {
    a = automata::translate(f);
    benchmark::DoNotOptimize(a);
  }
  report(state, a);
}
BENCHMARK(BM_OursDwyer)->DenseRange(0, 54)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
