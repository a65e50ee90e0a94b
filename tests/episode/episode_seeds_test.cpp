// The end-to-end bar: 30 seeded episodes each of relocate, add and
// remove on 3-block-tray and on 3-block all succeed, with a complete log
// (first line "episode", last line "end" with success). Slow: ~180 episodes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "rtamp/episode/episode.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace rtamp::episode {
namespace {

using Kind = world::Intervention::Kind;

}  // namespace
}  // namespace rtamp::episode

namespace rtamp::world {
void PrintTo(Intervention::Kind k, std::ostream* os) {
  *os << (k == Intervention::Kind::Relocate ? "relocate" : k == Intervention::Kind::Add ? "add" : "remove");
}
}  // namespace rtamp::world

namespace rtamp::episode {
namespace {

class SeededEpisodes : public ::testing::TestWithParam<std::tuple<std::string, Kind>> {};

TEST_P(SeededEpisodes, AllSucceed) {
  const auto& [name, kind] = GetParam();
  const world::Scenario s = world::load_scenario(name);
  const std::string log = (std::filesystem::temp_directory_path() /
                           ("rtamp_seeded_" + name + "_" + std::to_string(static_cast<int>(kind)) + ".jsonl"))
                              .string();
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    EpisodeOptions o;
    o.seed = seed;
    o.person.change = world::RandomChange{kind};
    o.randomize_initial = true;
    o.scripted_operator = false;
    o.loop.max_time = 300;
    o.outputs.log = log;
    const EpisodeMetrics m = run_episode(s, o);
    EXPECT_TRUE(m.success) << name << " seed " << seed << ": " << m.reason;
    EXPECT_EQ(m.interventions, 1) << "seed " << seed;
    std::ifstream in(log);
    std::string line, first, last;
    while (std::getline(in, line)) {
      if (first.empty()) first = line;
      last = line;
    }
    const auto end = nlohmann::json::parse(last);
    EXPECT_EQ(nlohmann::json::parse(first).at("ev"), "episode");
    EXPECT_EQ(end.at("ev"), "end");
    EXPECT_EQ(end.at("success"), m.success);
  }
  std::filesystem::remove(log);
}

INSTANTIATE_TEST_SUITE_P(Changes, SeededEpisodes,
                         ::testing::Combine(::testing::Values("3-block-tray", "3-block"),
                                            ::testing::Values(Kind::Relocate, Kind::Add, Kind::Remove)),
                         [](const auto& tp) {
                           const std::string s = std::get<0>(tp.param) == "3-block" ? "Blocks" : "Tray";
                           const Kind k = std::get<1>(tp.param);
                           return s + (k == Kind::Relocate ? "Relocate" : k == Kind::Add ? "Add" : "Remove");
                         });

}  // namespace
}  // namespace rtamp::episode
