// Randomized oracle test of the translator (see random_oracle.hpp): 500 and
// 5,000 random formulas of tree size 1..15 over 3-4 atoms, 50 lassos each.
#include "random_oracle.hpp"

namespace rtamp::automata {
namespace {

TEST(TranslateRandom, Quick) { test::run_random_oracle(1, 500, 50); }

TEST(TranslateRandom, Large) { test::run_random_oracle(2024, 5000, 50); }

}  // namespace
}  // namespace rtamp::automata
