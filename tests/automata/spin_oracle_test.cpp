// spin as an independent oracle for the translator: for X-free formulas (the
// Dwyer patterns and robot patterns without X, and random formulas) run
// `spin -f` (with a 5 s limit), read its never claim with our reader, and
// check that spin's automaton, ours (BA and TGBA) and the direct LTL semantics
// (ltl::holds) agree on random lasso words. Skipped when spin is not installed.
// This also exercises the never-claim reader on everything spin prints.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <random>
#include <set>

#include "io_lasso_words.hpp"
#include "rtamp/automata/never_claim_reader.hpp"
#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/lasso.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/ltl/printer.hpp"
#include "rtamp/ltl/random.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp_source_dir.hpp"

using namespace rtamp;
using namespace rtamp::automata;
using rtamp::automata::testing::accepts;

namespace {

bool have_spin() { return std::system("command -v spin >/dev/null 2>&1 && command -v timeout >/dev/null 2>&1") == 0; }

bool has_next(const ltl::Formula& f) {
  if (f.is(ltl::Op::Next)) return true;
  for (const auto& c : f.children())
    if (has_next(c)) return true;
  return false;
}

void collect_atoms(const ltl::Formula& f, std::set<std::string>& out) {
  if (f.is(ltl::Op::Atom)) out.insert(f.name());
  for (const auto& c : f.children()) collect_atoms(c, out);
}

// spin's never claim for f, read back, with spin's atom names mapped back to
// ours; nullopt if spin failed or ran out of time.
std::optional<Automaton> spin_automaton(const ltl::Formula& f, std::string& claim) {
  std::map<std::string, std::string> renamed;
  const std::string text = ltl::to_spin_string(f, &renamed);
  // 5 s of spin's CPU time (ulimit -t: the same on a loaded machine as on an idle
  // one, unlike a wall-clock limit), and a wall-clock guard against a hang.
  const std::string cmd = "ulimit -t 5; exec timeout 300 spin -f '" + text + "' 2>&1";
  FILE* p = ::popen(cmd.c_str(), "r");
  if (!p) return std::nullopt;
  claim.clear();
  std::array<char, 4096> buf{};
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), p)) > 0) claim.append(buf.data(), n);
  const int status = ::pclose(p);
  if (status != 0 || claim.rfind("never", 0) != 0) return std::nullopt;
  Automaton a = read_never_claim(claim, "spin -f '" + text + "'");
  for (auto& atom : a.atoms)
    if (auto it = renamed.find(atom); it != renamed.end()) atom = it->second;
  return a;
}

struct Tally {
  int checked = 0;
  int spin_failed = 0;
  std::vector<std::string> failed;  // formulas spin failed on (for the message)
};

void check_formula(const ltl::Formula& f, std::mt19937_64& rng, Tally& tally) {
  std::string claim;
  const auto spin = spin_automaton(f, claim);
  if (!spin) {
    ++tally.spin_failed;
    tally.failed.push_back(ltl::to_string(f));
    return;
  }
  ++tally.checked;
  TranslateOptions tgba;
  tgba.state_based = false;
  const Automaton ba = translate(f);
  const Automaton gba = translate(f, tgba);
  std::set<std::string> atom_set;
  collect_atoms(f, atom_set);
  std::vector<std::string> atoms(atom_set.begin(), atom_set.end());
  if (atoms.empty()) atoms = {"a"};
  // Report the first disagreement of each automaton, then go on with the
  // next formula (so one run lists every formula that goes wrong).
  bool spin_ok = true, ba_ok = true, gba_ok = true;
  for (int i = 0; i < 150; ++i) {
    const ltl::LassoWord w = ltl::random_lasso(rng, atoms, 3, 4);
    const bool truth = ltl::holds(f, w);
    if (spin_ok && accepts(*spin, w) != truth) {
      spin_ok = false;
      ADD_FAILURE() << "spin's automaton disagrees with the LTL semantics on " << ltl::to_string(f) << " / "
                    << ltl::to_string(w) << " (holds: " << truth << ")\n"
                    << claim;
    }
    if (ba_ok && accepts(ba, w) != truth) {
      ba_ok = false;
      ADD_FAILURE() << "our BA disagrees with the LTL semantics (and spin) on " << ltl::to_string(f) << " / "
                    << ltl::to_string(w) << " (holds: " << truth << ")";
    }
    if (gba_ok && accepts(gba, w) != truth) {
      gba_ok = false;
      ADD_FAILURE() << "our TGBA disagrees with the LTL semantics (and spin) on " << ltl::to_string(f) << " / "
                    << ltl::to_string(w) << " (holds: " << truth << ")";
    }
  }
}

std::vector<ltl::Formula> formulas_from(const std::string& path) {
  std::ifstream in(path);
  std::vector<ltl::Formula> out;
  std::string line;
  while (std::getline(in, line)) {
    const auto first = line.find_first_not_of(" \t");
    if (first == std::string::npos || line[first] == '#') continue;
    out.push_back(ltl::parse(line));
  }
  return out;
}

}  // namespace

TEST(SpinOracle, PatternFormulasWithoutNext) {
  if (!have_spin()) GTEST_SKIP() << "spin (or coreutils timeout) is not installed";
  std::mt19937_64 rng(7);
  Tally tally;
  int total = 0;
  for (const char* file : {"/tests/data/dac-patterns.ltl", "/tests/data/robot-patterns.ltl"}) {
    const auto fs = formulas_from(std::string(RTAMP_SOURCE_DIR) + file);
    ASSERT_FALSE(fs.empty()) << file;
    for (const auto& f : fs) {
      if (has_next(f)) continue;
      ++total;
      check_formula(f, rng, tally);
    }
  }
  RecordProperty("checked", tally.checked);
  EXPECT_GE(total, 45);
  // spin needs more than 5 s on a few long Dwyer patterns (its W is expanded
  // into nested V with duplicated operands): 4 of 48 on our machine.
  EXPECT_GE(tally.checked, total - 6) << tally.spin_failed << " spin runs failed or timed out";
}

TEST(SpinOracle, RandomFormulasWithoutNext) {
  if (!have_spin()) GTEST_SKIP() << "spin (or coreutils timeout) is not installed";
  std::mt19937_64 rng(11);
  ltl::RandomFormulaOptions opt;
  opt.atoms = {"a", "b", "c"};
  opt.set_weight(ltl::Op::Next, 0);
  Tally tally;
  for (int i = 0; i < 300; ++i) {
    opt.size = static_cast<std::size_t>(ltl::uniform(rng, 4, 20));
    const ltl::Formula f = ltl::random_formula(rng, opt);
    ASSERT_FALSE(has_next(f));
    check_formula(f, rng, tally);
  }
  // spin is slow on a few large formulas; most must have been checked.
  EXPECT_GE(tally.checked, 285) << tally.spin_failed << " spin runs failed or timed out";
}
