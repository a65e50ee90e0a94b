// The big randomized oracle run (label slow): 100,000 random formulas of tree
// size up to 20, 50 lassos each, BA and TGBA, with and without reductions.
#include "random_oracle.hpp"

namespace rtamp::automata {
namespace {

TEST(TranslateRandomSlow, Size15) { test::run_random_oracle(77, 60000, 50, 15); }

TEST(TranslateRandomSlow, Size20) { test::run_random_oracle(78, 40000, 50, 20); }

}  // namespace
}  // namespace rtamp::automata
