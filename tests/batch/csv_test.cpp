// The batch CSV: quoting, write → read round trips (including awkward
// reasons and exact doubles), and the reader's refusals.
#include "rtamp/batch/csv.hpp"

#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "rtamp/util/error.hpp"

namespace {

using namespace rtamp::batch;

EpisodeRecord sample(int trial, std::string reason = "task done") {
  EpisodeRecord r;
  r.scenario = "3-block-tray";
  r.algorithm = "astar-exp";
  r.bt = "online-action";
  r.change = "relocate";
  r.trial = trial;
  r.seed = 0xFFFFFFFFFFFFFFFFull - static_cast<std::uint64_t>(trial);
  r.success = trial % 3 != 0;
  r.reason = std::move(reason);
  r.first_plan_s = 0.1 * trial + 1e-17;
  r.replan_s = 1.0 / 3.0 * trial;
  r.replans = trial % 4;
  r.tree_changes = static_cast<std::uint64_t>(trial) * 5;
  r.completion_s = 123.456789 + trial;
  r.motion_cost = 6.02214076e23 / (trial + 1);
  r.interventions = 1;
  r.wall_s = 2.5e-7 * trial;
  r.rtf = 31.7;
  return r;
}

std::string to_text(const std::vector<EpisodeRecord>& rs) {
  std::ostringstream o;
  write_csv(o, rs);
  return o.str();
}

TEST(Csv, QuoteOnlyWhenNeeded) {
  EXPECT_EQ(csv_quote("plain"), "plain");
  EXPECT_EQ(csv_quote(""), "");
  EXPECT_EQ(csv_quote("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_quote("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(csv_quote("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(csv_quote("cr\r"), "\"cr\r\"");
  EXPECT_EQ(csv_quote(" lead"), "\" lead\"");
  EXPECT_EQ(csv_quote("trail "), "\"trail \"");
  EXPECT_EQ(csv_line({"a", "b,c", ""}), "a,\"b,c\",");
}

TEST(Csv, HeaderIsThePublishedColumnList) {
  std::ostringstream o;
  write_header(o);
  EXPECT_EQ(o.str(),
            "scenario,algorithm,bt,change,trial,seed,success,reason,first_plan_s,replan_s,replans,tree_changes,"
            "completion_s,motion_cost,interventions,wall_s,rtf\n");
}

TEST(Csv, RoundTripIsIdentity) {
  std::vector<EpisodeRecord> rs;
  const char* reasons[] = {"task done",
                           "no plan: region r2, full",
                           "quote \"inside\" and, comma",
                           "multi\nline\r\nreason",
                           "",
                           " padded ",
                           "\"",
                           ",",
                           "ünïcödé ±"};
  int t = 1;
  for (const char* why : reasons) rs.push_back(sample(t++, why));
  const std::string text = to_text(rs);
  const auto back = read_csv(text, "mem.csv");
  ASSERT_EQ(back.size(), rs.size());
  for (std::size_t i = 0; i < rs.size(); ++i) EXPECT_EQ(back[i], rs[i]) << i;
  // Writing again gives the same bytes.
  EXPECT_EQ(to_text(back), text);
}

TEST(Csv, RandomDoublesRoundTripExactly) {
  std::mt19937_64 rng(3);
  std::vector<EpisodeRecord> rs;
  for (int i = 1; i <= 200; ++i) {
    EpisodeRecord r = sample(i);
    std::uniform_real_distribution<double> u(0, 1e4);
    r.first_plan_s = u(rng);
    r.replan_s = std::ldexp(u(rng), -40);
    r.completion_s = u(rng) * 1e6;
    rs.push_back(r);
  }
  const auto back = read_csv(to_text(rs));
  ASSERT_EQ(back.size(), rs.size());
  for (std::size_t i = 0; i < rs.size(); ++i) EXPECT_EQ(back[i], rs[i]);
}

TEST(Csv, ReadsCrLfAndBlankLastLine) {
  std::string text = to_text({sample(1), sample(2)});
  std::string crlf;
  for (char c : text) {
    if (c == '\n') crlf += '\r';
    crlf += c;
  }
  const auto back = read_csv(crlf + "\r\n");
  ASSERT_EQ(back.size(), 2u);
  EXPECT_EQ(back[1], sample(2));
}

TEST(Csv, ParserHandlesQuotedFieldsAcrossLines) {
  const auto rows = parse_csv("a,\"b\nc\",d\ne,\"\",\"x\"\"y\"\n");
  ASSERT_EQ(rows.rows.size(), 2u);
  EXPECT_EQ(rows.rows[0], (std::vector<std::string>{"a", "b\nc", "d"}));
  EXPECT_EQ(rows.rows[1], (std::vector<std::string>{"e", "", "x\"y"}));
  EXPECT_EQ(rows.lines[0], 1);
  EXPECT_EQ(rows.lines[1], 3);
}

std::string error_of(const std::string& text) {
  try {
    read_csv(text, "f.csv");
  } catch (const rtamp::Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Csv, RejectsBrokenInputWithLocation) {
  const std::string good = to_text({sample(1)});
  const std::string header = good.substr(0, good.find('\n') + 1);
  const std::string row = good.substr(good.find('\n') + 1);
  EXPECT_NE(error_of("").find("empty"), std::string::npos);
  EXPECT_NE(error_of("scenario,algo\n").find("header"), std::string::npos);
  EXPECT_NE(error_of(header + "a,b,c\n").find("f.csv:2"), std::string::npos);
  // Unterminated quote.
  EXPECT_NE(error_of(header + "3-block,\"astar\n").find("unterminated"), std::string::npos);
  // Stray quote and text after a closing quote.
  EXPECT_NE(error_of(header + "3-bl\"ock," + row).find("stray"), std::string::npos);
  EXPECT_NE(error_of(header + "\"3-block\"x," + row).find("after the closing quote"), std::string::npos);
  auto replace_field = [&](int index, const std::string& value) {
    auto rows = parse_csv(row).rows.front();
    rows[static_cast<std::size_t>(index)] = value;
    return header + csv_line(rows) + "\n";
  };
  EXPECT_NE(error_of(replace_field(1, "bfs")).find("unknown algorithm"), std::string::npos);
  EXPECT_NE(error_of(replace_field(2, "online")).find("unknown BT variant"), std::string::npos);
  EXPECT_NE(error_of(replace_field(3, "move")).find("unknown change"), std::string::npos);
  EXPECT_NE(error_of(replace_field(4, "0")).find("trial"), std::string::npos);
  EXPECT_NE(error_of(replace_field(6, "yes")).find("success"), std::string::npos);
  EXPECT_NE(error_of(replace_field(8, "1.5s")).find("first_plan_s"), std::string::npos);
  EXPECT_NE(error_of(replace_field(9, "nan")).find("replan_s"), std::string::npos);
  EXPECT_NE(error_of(replace_field(9, "inf")).find("replan_s"), std::string::npos);
  EXPECT_NE(error_of(replace_field(10, "-1")).find("replans"), std::string::npos);
  EXPECT_NE(error_of(replace_field(0, "")).find("scenario"), std::string::npos);
  // The line number of the bad row is reported.
  EXPECT_NE(error_of(header + row + row.substr(0, row.size() - 1) + ",extra\n").find("f.csv:3"), std::string::npos);
}

}  // namespace
