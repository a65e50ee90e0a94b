// Planning benchmarks (docs/benchmarks.md).
//
// Google Benchmark cases (make bench):
//   BM_TrayFirstPlan/<algo>        plan() of a fresh Planner on 3-block-tray (euclid)
//   BM_TrayReplan/<change>/<algo>/<ik>  apply(change) + plan() after a first plan; the
//                                  change is undone (untimed) between iterations
//                                  (ik = 1: the `ik` cost model, astar-exp only)
//   BM_TrayColdReplan/<change>/<ik> the same replans from scratch: a fresh Planner
//                                  for the changed world, A*, no experience (euclid or ik)
//   BM_TrayReplanStream/<algo>      replans along 20-state streams of executed steps and
//                                  relocations, fresh planner per stream (mean per replan)
//   BM_PartialVsFull/<n>/<full>    cold A* plans on 5-region random layouts, 10 seeds
// Report mode (the paper's partial-vs-full experiment and the replan table as CSV):
//   plan_bench --csv-dir=DIR [--full-max=N]
// writes DIR/partial-vs-full.csv and DIR/replan.csv and prints a summary;
//   plan_bench --csv-dir=DIR --full-growth
// grows n until full construction passes 60 s or 8 GiB (DIR/full-growth.csv).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include "rtamp/plan/planner.hpp"
#include "rtamp/robot/ik_motion_cost.hpp"
#include "rtamp/world/generator.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

const plan::Algorithm kAlgos[] = {plan::Algorithm::Dijkstra, plan::Algorithm::AStar,
                                  plan::Algorithm::AStarExperience};

plan::PlannerOptions options(plan::Algorithm a, plan::GraphConstruction g = plan::GraphConstruction::Partial) {
  plan::PlannerOptions o;
  o.algorithm = a;
  o.graph = g;
  o.cost = "euclid";
  return o;
}

const world::Scenario& tray() {
  static const world::Scenario s = world::load_scenario("3-block-tray");
  return s;
}

// A change and the change that undoes it, by kind.
struct ChangePair {
  world::Change apply, undo;
};
std::vector<ChangePair> changes_of_kind(const std::string& kind) {
  using world::Change;
  std::vector<ChangePair> out;
  if (kind == "relocate") {
    for (const char* o : {"o1", "o2", "o3"})
      for (const char* l : {"r2", "r3"}) out.push_back({Change::relocate(o, l), Change::relocate(o, "r1")});
  } else if (kind == "add") {
    for (const char* l : {"r1", "r2", "r3"})
      out.push_back({Change::add_object("o4", "block", l), Change::remove_object("o4")});
  } else {  // remove
    for (const char* o : {"o1", "o2", "o3"}) out.push_back({Change::remove_object(o), Change::add_object(o, "block", "r1")});
  }
  return out;
}

void BM_TrayFirstPlan(benchmark::State& state) {
  const auto algo = kAlgos[state.range(0)];
  std::size_t nodes = 0;
  for (auto _ : state) {
    plan::Planner p(tray(), options(algo));
    const auto t0 = Clock::now();
    auto r = p.plan();
    state.SetIterationTime(since(t0));
    nodes = r.stats.generated;
    benchmark::DoNotOptimize(r);
  }
  state.counters["generated"] = double(nodes);
  state.SetLabel(plan::to_string(algo));
}
BENCHMARK(BM_TrayFirstPlan)->DenseRange(0, 2)->UseManualTime()->Unit(benchmark::kMicrosecond);

// Options with the `euclid` model, or with the `ik` model (UR5 skill paths; a
// fresh model, so an empty IK cache, each time it is called).
plan::PlannerOptions options_for(plan::Algorithm a, bool ik) {
  plan::PlannerOptions o = options(a);
  if (ik) o.model = std::make_shared<robot::IkMotionCost>(robot::IkMotionCost::params_for(tray()));
  return o;
}

void BM_TrayReplan(benchmark::State& state) {
  const char* kinds[] = {"relocate", "add", "remove"};
  const std::string kind = kinds[state.range(0)];
  const auto algo = kAlgos[state.range(1)];
  const bool ik = state.range(2) != 0;
  const auto pairs = changes_of_kind(kind);
  plan::Planner p(tray(), options_for(algo, ik));
  (void)p.plan();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& c = pairs[i++ % pairs.size()];
    const auto t0 = Clock::now();
    p.apply(c.apply, plan::Planner::ChangeOrigin::Observed);  // a person did it, as the loop sees it
    auto r = p.plan();
    state.SetIterationTime(since(t0));
    benchmark::DoNotOptimize(r);
    p.apply(c.undo, plan::Planner::ChangeOrigin::Observed);
    (void)p.plan();
  }
  state.SetLabel(kind + "/" + plan::to_string(algo) + (ik ? "/ik" : ""));
}
BENCHMARK(BM_TrayReplan)
    ->ArgsProduct({{0, 1, 2}, {0, 1, 2}, {0}})
    ->Args({0, 2, 1})
    ->Args({1, 2, 1})
    ->Args({2, 2, 1})
    ->UseManualTime()
    ->Unit(benchmark::kMicrosecond);

// The cold baseline of a replan: no experience at all. After the change (made
// untimed on a warm planner), a fresh Planner is built for the changed world
// (transition system, labeling, empty product graph and cost cache; the
// automaton is given, translation is not timed) and plans with A*.
void BM_TrayColdReplan(benchmark::State& state) {
  const char* kinds[] = {"relocate", "add", "remove"};
  const std::string kind = kinds[state.range(0)];
  const bool ik = state.range(1) != 0;
  const auto pairs = changes_of_kind(kind);
  plan::Planner warm(tray(), options(plan::Algorithm::AStar));
  (void)warm.plan();
  std::size_t i = 0;
  for (auto _ : state) {
    const auto& c = pairs[i++ % pairs.size()];
    warm.apply(c.apply, plan::Planner::ChangeOrigin::Observed);
    const auto t0 = Clock::now();
    plan::Planner cold(warm.scenario(), warm.automaton(), options_for(plan::Algorithm::AStar, ik));
    cold.set_placement(warm.placement(), warm.hand());
    auto r = cold.plan();
    state.SetIterationTime(since(t0));
    benchmark::DoNotOptimize(r);
    warm.apply(c.undo, plan::Planner::ChangeOrigin::Observed);
  }
  state.SetLabel(kind + "/cold-astar/" + (ik ? "ik" : "euclid"));
}
BENCHMARK(BM_TrayColdReplan)->ArgsProduct({{0, 1, 2}, {0, 1}})->UseManualTime()->Unit(benchmark::kMicrosecond);


// Replans as an episode makes them: a stream of 20 states, each reached from
// the one before either by the robot doing the first step of its plan (2 in
// 3) or by a person moving a random block to a random location (r1, r2 or
// the tray; also whenever the task is done). Ten seeded streams, made once
// with astar-exp plans. Each iteration takes a fresh planner (first plan
// untimed), then times plan() from each state of one stream in order
// (set_placement: the TS is unchanged, as in an episode with relocations).
// Reported time: the mean per replan. astar rebuilds its graph every time;
// astar-exp starts with no experience and accumulates it along the stream.
struct StreamState {
  world::Placement placement;
  std::string hand;
};
const std::vector<std::vector<StreamState>>& replan_streams() {
  static const std::vector<std::vector<StreamState>> streams = [] {
    std::vector<std::vector<StreamState>> out;
    const char* blocks[] = {"o1", "o2", "o3"};
    const char* locs[] = {"r1", "r2", "r3"};
    for (std::uint32_t seed = 1; seed <= 10; ++seed) {
      std::mt19937 rng(seed);
      plan::Planner gen(tray());
      std::vector<StreamState> stream;
      while (stream.size() < 20) {
        const auto r = gen.plan();
        bool moves = false;
        if (r.found)
          for (const auto& st : r.plan.prefix) moves = moves || !st.action.is_stay();
        if (moves && rng() % 3 != 0) {
          gen.execute(r.plan.prefix.front().action);
        } else {
          const std::string& block = blocks[rng() % 3];  // one draw per statement
          gen.apply(world::Change::relocate(block, locs[rng() % 3]), plan::Planner::ChangeOrigin::Observed);
        }
        stream.push_back({gen.placement(), gen.hand()});
      }
      out.push_back(std::move(stream));
    }
    return out;
  }();
  return streams;
}

void BM_TrayReplanStream(benchmark::State& state) {
  const auto algo = kAlgos[state.range(0)];
  const auto& streams = replan_streams();
  std::size_t i = 0;
  double expanded = 0, replans = 0;
  for (auto _ : state) {
    const auto& stream = streams[i++ % streams.size()];
    plan::Planner p(tray(), options(algo));
    (void)p.plan();
    double t = 0;
    for (const auto& st : stream) {
      p.set_placement(st.placement, st.hand);
      const auto t0 = Clock::now();
      auto r = p.plan();
      t += since(t0);
      expanded += double(r.stats.expanded);
      benchmark::DoNotOptimize(r);
    }
    replans += double(stream.size());
    state.SetIterationTime(t / double(stream.size()));
  }
  state.counters["expanded_per_replan"] = expanded / replans;
  state.SetLabel(plan::to_string(algo));
}
BENCHMARK(BM_TrayReplanStream)->Arg(1)->Arg(2)->UseManualTime()->Unit(benchmark::kMicrosecond);

world::Scenario random_layout(int n, std::uint64_t seed) {
  world::GeneratorOptions g;
  g.regions = 5;
  g.objects = n;
  g.layout = world::GeneratorOptions::Layout::Random;
  g.seed = seed;
  return world::generate_scenario(g);
}

void BM_PartialVsFull(benchmark::State& state) {
  const int n = static_cast<int>(state.range(0));
  const bool full = state.range(1) != 0;
  std::vector<world::Scenario> scenes;
  for (std::uint64_t s = 1; s <= 10; ++s) scenes.push_back(random_layout(n, s));
  std::size_t gen = 0, exp = 0, mem = 0;
  for (auto _ : state) {
    double t = 0;
    gen = exp = mem = 0;
    for (const auto& sc : scenes) {
      plan::Planner p(sc, options(plan::Algorithm::AStar,
                                  full ? plan::GraphConstruction::Full : plan::GraphConstruction::Partial));
      const auto t0 = Clock::now();
      auto r = p.plan();
      t += since(t0);
      gen += r.stats.generated;
      exp += r.stats.expanded;
      mem += r.stats.memory_bytes;
    }
    state.SetIterationTime(t / double(scenes.size()));
  }
  state.counters["generated"] = double(gen) / 10;
  state.counters["expanded"] = double(exp) / 10;
  state.counters["memory_bytes"] = double(mem) / 10;
  state.SetLabel(full ? "full" : "partial");
}
BENCHMARK(BM_PartialVsFull)
    ->ArgsProduct({{2, 3, 4, 5, 6}, {0, 1}})
    ->Args({8, 0})
    ->Args({10, 0})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

// ---- report mode -------------------------------------------------------------

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}
double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[std::min(v.size() - 1, static_cast<std::size_t>(p * double(v.size())))];
}

void report_partial_vs_full(const std::string& dir, int full_max) {
  std::ofstream csv(dir + "/partial-vs-full.csv");
  csv << "n,construction,symmetry,seed,seconds,construction_seconds,generated,expanded,graph_nodes,graph_edges,memory_bytes,"
         "bytes_per_node,cost,found\n";
  std::cout << "partial vs full (5 regions, random layouts, cold A*, euclid; median of 3 runs per layout)\n";
  std::cout << "  n construction sym  mean_ms   max_ms  mean_generated  mean_expanded  mean_MiB  B/node\n";
  for (int sym = 1; sym >= 0; --sym)
  for (int n = 2; n <= 10; ++n)
    for (int full = 0; full <= 1; ++full) {
      if (full && n > full_max) continue;
      // Without the symmetry reduction (the paper's state space): partial up to 7, full up to 6.
      if (!sym && (full ? n > std::min(full_max, 6) : n > 7)) continue;
      std::vector<double> times;
      double gen = 0, expd = 0, mem = 0, bpn = 0;
      for (std::uint64_t seed = 1; seed <= 10; ++seed) {
        const auto sc = random_layout(n, seed);
        std::vector<double> runs;
        plan::PlanResult last;
        for (int k = 0; k < 3; ++k) {
          plan::PlannerOptions o =
              options(plan::Algorithm::AStar, full ? plan::GraphConstruction::Full : plan::GraphConstruction::Partial);
          o.limits.max_nodes = 200'000'000;
          o.limits.max_memory_bytes = 0;  // the node and time limits bound these runs
          o.symmetry = sym != 0;
          o.limits.time_limit = 120;
          plan::Planner p(sc, o);
          last = p.plan();
          runs.push_back(last.stats.seconds);
          if (full && last.stats.seconds > 5) break;  // slow: one run is enough
        }
        const double t = median(runs);
        const auto& s = last.stats;
        csv << n << "," << (full ? "full" : "partial") << "," << sym << "," << seed << "," << t << "," << s.construction_seconds << ","
            << s.generated << "," << s.expanded << "," << s.graph_nodes << "," << s.graph_edges << "," << s.memory_bytes
            << "," << s.bytes_per_node() << "," << (last.found ? last.plan.cost() : -1) << "," << last.found << "\n";
        csv.flush();
        times.push_back(t);
        gen += double(s.generated);
        expd += double(s.expanded);
        mem += double(s.memory_bytes);
        bpn += s.bytes_per_node();
      }
      double mean = 0;
      for (double t : times) mean += t;
      mean /= double(times.size());
      std::printf("%3d %-12s %3d %8.3f %8.3f %15.0f %14.0f %9.2f %7.1f\n", n, full ? "full" : "partial", sym, mean * 1e3,
                  *std::max_element(times.begin(), times.end()) * 1e3, gen / 10, expd / 10, mem / 10 / (1 << 20),
                  bpn / 10);
      std::fflush(stdout);
    }
}

void report_replan(const std::string& dir) {
  std::ofstream csv(dir + "/replan.csv");
  csv << "algorithm,change,trial,seconds,plan_seconds,generated,expanded,cache_hits,cache_misses,cost\n";
  std::cout << "\n3-block-tray (euclid, partial): first plan and replans (apply + plan wall time)\n";
  std::cout << "algorithm  change    median_us  p90_us  mean_generated  mean_expanded\n";
  for (auto algo : kAlgos) {
    {
      std::vector<double> t;
      for (int k = 0; k < 201; ++k) {
        plan::Planner p(tray(), options(algo));
        const auto t0 = Clock::now();
        auto r = p.plan();
        t.push_back(since(t0));
      }
      std::printf("%-10s %-9s %9.1f %7.1f\n", plan::to_string(algo), "first", median(t) * 1e6,
                  percentile(t, 0.9) * 1e6);
      for (std::size_t k = 0; k < t.size(); ++k)
        csv << plan::to_string(algo) << ",first," << k << "," << t[k] << ",,,,,,\n";
    }
    for (const char* kind : {"relocate", "add", "remove"}) {
      const auto pairs = changes_of_kind(kind);
      plan::Planner p(tray(), options(algo));
      (void)p.plan();
      std::vector<double> t;
      double gen = 0, expd = 0;
      const int trials = 301;
      for (int k = 0; k < trials; ++k) {
        const auto& c = pairs[static_cast<std::size_t>(k) % pairs.size()];
        const auto t0 = Clock::now();
        p.apply(c.apply, plan::Planner::ChangeOrigin::Observed);  // a person did it, as the loop sees it
        auto r = p.plan();
        const double dt = since(t0);
        t.push_back(dt);
        gen += double(r.stats.generated);
        expd += double(r.stats.expanded);
        csv << plan::to_string(algo) << "," << kind << "," << k << "," << dt << "," << r.stats.seconds << ","
            << r.stats.generated << "," << r.stats.expanded << "," << r.stats.cache_hits << "," << r.stats.cache_misses
            << "," << (r.found ? r.plan.cost() : -1) << "\n";
        p.apply(c.undo, plan::Planner::ChangeOrigin::Observed);
        (void)p.plan();
      }
      std::printf("%-10s %-9s %9.1f %7.1f %15.1f %14.1f\n", plan::to_string(algo), kind, median(t) * 1e6,
                  percentile(t, 0.9) * 1e6, gen / trials, expd / trials);
      std::fflush(stdout);
    }
  }
}

}  // namespace

// Full construction in the paper's state space (no symmetry reduction), one
// layout (seed 1) per n, n = 2, 3, ... until a full construction passes 60 s or
// 8 GiB (the product graph's memory; the node limit keeps it below that), with
// the partial construction at the same n beside it. Writes DIR/full-growth.csv.
void report_full_growth(const std::string& dir) {
  std::ofstream csv(dir + "/full-growth.csv");
  csv << "n,construction,seconds,construction_seconds,generated,expanded,graph_nodes,memory_bytes,found,stopped\n";
  std::cout << "full construction until 60 s or 8 GiB (5 regions, random layout seed 1, A*, euclid, no symmetry)\n";
  std::cout << "  n construction   seconds   graph_nodes   memory_MiB  stopped\n";
  constexpr double kMaxBytes = 8.0 * (1ull << 30);
  for (int n = 2; n <= 12; ++n) {
    bool stop = false;
    for (int full = 1; full >= 0; --full) {
      plan::PlannerOptions o =
          options(plan::Algorithm::AStar, full ? plan::GraphConstruction::Full : plan::GraphConstruction::Partial);
      o.symmetry = false;
      o.limits.time_limit = 60;
      o.limits.max_nodes = 25'000'000;  // at ~300 B/node the graph stays near 8 GiB
      o.limits.max_memory_bytes = 0;
      plan::Planner p(random_layout(n, 1), o);
      const plan::PlanResult r = p.plan();
      const auto& st = r.stats;
      const char* why = st.hit_time_limit                                 ? "60 s"
                        : st.hit_node_limit || double(st.memory_bytes) > kMaxBytes ? "8 GiB"
                                                                           : "";
      csv << n << "," << (full ? "full" : "partial") << "," << st.seconds << "," << st.construction_seconds << ","
          << st.generated << "," << st.expanded << "," << st.graph_nodes << "," << st.memory_bytes << "," << r.found
          << "," << why << "\n";
      csv.flush();
      std::printf("%3d %-12s %9.3f %13llu %12.1f  %s\n", n, full ? "full" : "partial", st.seconds,
                  static_cast<unsigned long long>(st.graph_nodes), double(st.memory_bytes) / (1 << 20), why);
      std::fflush(stdout);
      if (full && *why) stop = true;
    }
    if (stop) break;
  }
}

int main(int argc, char** argv) {
  std::string dir;
  int full_max = 7;
  bool full_growth = false;
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], "--csv-dir=", 10) == 0) dir = argv[i] + 10;
    else if (std::strncmp(argv[i], "--full-max=", 11) == 0) full_max = std::atoi(argv[i] + 11);
    else if (std::strcmp(argv[i], "--full-growth") == 0) full_growth = true;
    else rest.push_back(argv[i]);
  }
  if (!dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    if (ec || !std::ofstream(dir + "/.write-test")) {
      std::cerr << "plan_bench: cannot write into --csv-dir " << dir << (ec ? ": " + ec.message() : "") << "\n";
      return 2;
    }
    std::filesystem::remove(dir + "/.write-test", ec);
  }
  if (!dir.empty() && full_growth) {
    report_full_growth(dir);
    return 0;
  }
  if (!dir.empty()) {
    report_replan(dir);
    report_partial_vs_full(dir, full_max);
    return 0;
  }
  int n = static_cast<int>(rest.size());
  benchmark::Initialize(&n, rest.data());
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
