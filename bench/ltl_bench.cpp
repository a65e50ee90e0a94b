// LTL layer benchmarks: parse, simplify, nnf, print on the 55 Dwyer patterns
// (tests/data/dac-patterns.ltl) and the robot formulas; per-formula times are
// the reported time divided by the number of formulas (items/s).
#include <benchmark/benchmark.h>

#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/nnf.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp/ltl/simplify.hpp"
#include "rtamp_source_dir.hpp"

namespace {

using namespace rtamp::ltl;

std::vector<std::string> load(const char* name) {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/" + name);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty() && line[0] != '#') out.push_back(line);
  return out;
}

const std::vector<std::string>& dac() {
  static const std::vector<std::string> v = load("dac-patterns.ltl");
  return v;
}
const std::vector<std::string>& robot() {
  static const std::vector<std::string> v = load("robot-patterns.ltl");
  return v;
}

void BM_ParseDwyer(benchmark::State& state) {
  for (auto _ : state)
    for (const std::string& s : dac()) benchmark::DoNotOptimize(parse(s));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(dac().size()));
}
BENCHMARK(BM_ParseDwyer);

// Parse + simplify from text each time: what the translator pays per formula.
void BM_ParseSimplifyDwyer(benchmark::State& state) {
  for (auto _ : state)
    for (const std::string& s : dac()) benchmark::DoNotOptimize(simplify(parse(s)));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(dac().size()));
}
BENCHMARK(BM_ParseSimplifyDwyer);

// The same with the parsed formulas kept alive between iterations (nodes
// stay in the unique table: measures the rewriting itself).
void BM_SimplifyDwyerWarm(benchmark::State& state) {
  std::vector<Formula> fs;
  for (const std::string& s : dac()) fs.push_back(parse(s));
  std::vector<Formula> keep;
  for (const Formula& f : fs) keep.push_back(simplify(f));
  for (auto _ : state)
    for (const Formula& f : fs) benchmark::DoNotOptimize(simplify(f));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(fs.size()));
}
BENCHMARK(BM_SimplifyDwyerWarm);

void BM_NnfDwyer(benchmark::State& state) {
  std::vector<Formula> fs;
  for (const std::string& s : dac()) fs.push_back(parse(s));
  for (auto _ : state)
    for (const Formula& f : fs) benchmark::DoNotOptimize(nnf(f));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(fs.size()));
}
BENCHMARK(BM_NnfDwyer);

void BM_PrintDwyer(benchmark::State& state) {
  std::vector<Formula> fs;
  for (const std::string& s : dac()) fs.push_back(parse(s));
  for (auto _ : state)
    for (const Formula& f : fs) benchmark::DoNotOptimize(to_string(f));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(fs.size()));
}
BENCHMARK(BM_PrintDwyer);

void BM_ParseSimplifyRobot(benchmark::State& state) {
  for (auto _ : state)
    for (const std::string& s : robot()) benchmark::DoNotOptimize(simplify(parse(s)));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(robot().size()));
}
BENCHMARK(BM_ParseSimplifyRobot);

// Random formulas of tree size 30 (fresh each iteration, fixed seed).
void BM_SimplifyRandom30(benchmark::State& state) {
  std::mt19937_64 rng(42);
  RandomFormulaOptions opt;
  opt.size = 30;
  std::vector<Formula> fs;
  for (int i = 0; i < 200; ++i) fs.push_back(random_formula(rng, opt));
  for (auto _ : state)
    for (const Formula& f : fs) benchmark::DoNotOptimize(simplify(f));
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(fs.size()));
}
BENCHMARK(BM_SimplifyRandom30);

// The lasso oracle on a Dwyer pattern and an 8-position word.
void BM_LassoHolds(benchmark::State& state) {
  const Formula f = parse(dac()[44]);
  std::mt19937_64 rng(1);
  const LassoWord w = random_lasso(rng, {"p", "q", "r", "s", "t"}, 4, 4);
  for (auto _ : state) benchmark::DoNotOptimize(holds(f, w));
}
BENCHMARK(BM_LassoHolds);

// Parsing a 1 MB conjunction.
void BM_ParseOneMegabyte(benchmark::State& state) {
  std::string wide;
  int count = 0;
  while (wide.size() < (1u << 20)) {
    if (!wide.empty()) wide += " & ";
    wide += 'p';
    wide += std::to_string(count++ % 5000);
  }
  for (auto _ : state) benchmark::DoNotOptimize(parse(wide));
  state.SetBytesProcessed(state.iterations() * static_cast<int64_t>(wide.size()));
}
BENCHMARK(BM_ParseOneMegabyte);

}  // namespace

BENCHMARK_MAIN();
