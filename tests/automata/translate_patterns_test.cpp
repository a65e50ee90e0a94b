// The 55 Dwyer et al. specification patterns (tests/data/dac-patterns.ltl),
// the robot formulas (tests/data/robot-patterns.ltl) and the EH, p, SB and
// hkrss families (tests/data/*-patterns.ltl): translation checked against
// ltl::holds on random lassos, and the size tables of the state-based BA
// printed (sizes are asserted as per-family total bounds, never times).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "oracle.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::automata {
namespace {

std::vector<std::string> read_formulas(const std::string& file) {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/" + file);
  std::vector<std::string> out;
  std::string line;
  while (std::getline(in, line)) {
    const auto p = line.find_first_not_of(" \t");
    if (p == std::string::npos || line[p] == '#') continue;
    out.push_back(line);
  }
  return out;
}

// Under the sanitizers (about 10x slower) every third formula with 100 words: the Release
// run checks all of them with 300.
constexpr std::size_t kFormulaStride = RTAMP_SANITIZER_BUILD ? 3 : 1;
constexpr int kWords = RTAMP_SANITIZER_BUILD ? 100 : 300;

void check_file(const std::string& file, std::size_t expected_count) {
  const auto formulas = read_formulas(file);
  ASSERT_EQ(formulas.size(), expected_count);
  std::mt19937_64 rng(7);
  for (std::size_t i = 0; i < formulas.size(); i += kFormulaStride) {
    const std::string& text = formulas[i];
    const ltl::Formula f = ltl::parse(text);
    const Automaton ba = translate(f);
    std::vector<ltl::LassoWord> ws;
    for (int k = 0; k < kWords; ++k) ws.push_back(ltl::random_lasso(rng, ba.atoms, 5, 5));
    for (int variant = 0; variant < 12; ++variant) {
      TranslateOptions opt;
      opt.state_based = variant & 1;
      opt.reduce = variant & 2;
      opt.construction = static_cast<Construction>(variant / 4);
      Automaton a;
      try {
        a = translate(f, opt);
      } catch (const Error&) {
        // Past the resource bounds only without the reductions or with the
        // merged-destination construction alone (hkrss's X-chain of 13).
        ASSERT_TRUE(!opt.reduce || opt.construction == Construction::MergedDestinations) << text;
        continue;
      }
      for (const auto& w : ws)
        ASSERT_EQ(lasso_accept(a, test::to_word(a, w)), ltl::holds(f, w))
            << text << " word " << ltl::to_string(w) << " state_based=" << opt.state_based << " reduce=" << opt.reduce;
    }
  }
}

TEST(TranslatePatterns, DwyerCorrect) { check_file("dac-patterns.ltl", 55); }
TEST(TranslatePatterns, RobotCorrect) { check_file("robot-patterns.ltl", 20); }
TEST(TranslatePatterns, EtessamiHolzmannCorrect) { check_file("eh-patterns.ltl", 12); }
TEST(TranslatePatterns, PelanekCorrect) { check_file("p-patterns.ltl", 20); }
TEST(TranslatePatterns, SomenziBloemCorrect) { check_file("sb-patterns.ltl", 27); }
TEST(TranslatePatterns, HkrssCorrect) { check_file("hkrss-patterns.ltl", 55); }

// Spot's `ltl2tgba -B` states per formula (tests/data/spot-B-sizes.txt):
// spot[file][i] for formula i+1, and whether the line is a duplicate that
// Spot's own totals leave out.
struct SpotSizes {
  std::map<std::string, std::vector<std::pair<std::size_t, bool>>> by_file;
};

SpotSizes read_spot_sizes() {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/tests/data/spot-B-sizes.txt");
  SpotSizes out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    std::string file, dup;
    std::size_t index = 0, states = 0;
    ls >> file >> index >> states >> dup;
    auto& v = out.by_file[file];
    if (v.size() < index) v.resize(index);
    v[index - 1] = {states, dup == "dup"};
  }
  return out;
}

// State-based totals per family against Spot's `ltl2tgba -B` (Spot's
// tests/core/ltl2tgba2.test), per formula and in total, over Spot's
// deduplicated list (its published totals) and over the whole file. The
// bound is the deduplicated total reached here, a regression guard; no
// formula may exceed twice Spot's states.
TEST(TranslatePatterns, FamilySizeTable) {
  struct Family {
    const char* file;
    std::size_t bound;
  };
  const Family families[] = {{"dac-patterns.ltl", 209},
                             {"eh-patterns.ltl", 43},
                             {"p-patterns.ltl", 50},
                             {"sb-patterns.ltl", 81},
                             {"hkrss-patterns.ltl", 224}};
  const SpotSizes spot = read_spot_sizes();
  std::string summary;
  for (const Family& fam : families) {
    const auto formulas = read_formulas(fam.file);
    const auto& ref = spot.by_file.at(fam.file);
    ASSERT_EQ(ref.size(), formulas.size()) << fam.file;
    std::size_t states = 0, deterministic = 0, spot_all = 0, dedup = 0, spot_dedup = 0, larger = 0,
                smaller = 0;
    for (std::size_t i = 0; i < formulas.size(); ++i) {
      const Automaton ba = translate(ltl::parse(formulas[i]));
      const auto [s, dup] = ref[i];
      const std::size_t n = ba.num_states();
      states += n;
      spot_all += s;
      if (!dup) {
        dedup += n;
        spot_dedup += s;
      }
      deterministic += is_deterministic(ba);
      larger += n > s;
      smaller += n < s;
      if (n != s) std::printf("%-20s %3zu %4zu (Spot %zu)  %s\n", fam.file, i + 1, n, s, formulas[i].c_str());
      EXPECT_LE(n, 2 * s) << formulas[i];
    }
    char row[256];
    std::snprintf(row, sizeof row, "%-20s %9zu %7zu %7zu %9zu %9zu %7zu %7zu %5zu\n", fam.file,
                  formulas.size(), dedup, spot_dedup, states, spot_all, larger, smaller, deterministic);
    summary += row;
    EXPECT_LE(dedup, fam.bound) << fam.file;
  }
  std::printf("%-20s %9s %7s %7s %9s %9s %7s %7s %5s\n", "family", "formulas", "dedup", "Spot", "all",
              "Spot all", "larger", "smaller", "det");
  std::printf("%s", summary.c_str());
}

TEST(TranslatePatterns, DwyerSizeTable) {
  const auto formulas = read_formulas("dac-patterns.ltl");
  std::size_t states = 0, edges = 0, tstates = 0, tedges = 0;
  std::printf("%3s %6s %6s %6s %6s %9s  %s\n", "#", "BA st", "BA ed", "TGBA s", "TGBA e", "time(us)", "formula");
  for (std::size_t i = 0; i < formulas.size(); ++i) {
    const ltl::Formula f = ltl::parse(formulas[i]);
    const auto t0 = std::chrono::steady_clock::now();
    const Automaton ba = translate(f);
    const auto t1 = std::chrono::steady_clock::now();
    TranslateOptions o;
    o.state_based = false;
    const Automaton tg = translate(f, o);
    states += ba.num_states();
    edges += ba.num_edges();
    tstates += tg.num_states();
    tedges += tg.num_edges();
    std::printf("%3zu %6u %6zu %6u %6zu %9.1f  %s\n", i + 1, ba.num_states(), ba.num_edges(), tg.num_states(),
                tg.num_edges(), std::chrono::duration<double, std::micro>(t1 - t0).count(), formulas[i].c_str());
  }
  std::printf("total BA %zu states %zu edges; TGBA %zu states %zu edges\n", states, edges, tstates, tedges);
  EXPECT_LE(states, 209u);
}

}  // namespace
}  // namespace rtamp::automata
