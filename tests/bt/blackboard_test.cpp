#include "rtamp/bt/blackboard.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace rtamp::bt {
namespace {

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const BlackboardError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(Blackboard, TypedSetAndGet) {
  Blackboard bb;
  bb.set("n", 3);
  bb.set<std::string>("s", "hello");
  bb.set("v", std::vector<int>{1, 2});
  EXPECT_EQ(bb.get<int>("n"), 3);
  EXPECT_EQ(bb.get<std::string>("s"), "hello");
  EXPECT_EQ(bb.get<std::vector<int>>("v").size(), 2u);
  bb.set("n", 4);
  EXPECT_EQ(bb.get<int>("n"), 4);
  bb.get<int>("n") = 5;
  EXPECT_EQ(bb.get<int>("n"), 5);
  EXPECT_EQ(bb.size(), 3u);
  EXPECT_EQ(bb.keys(), (std::vector<std::string>{"n", "s", "v"}));
}

TEST(Blackboard, WrongTypeOnGetNamesKeyAndBothTypes) {
  Blackboard bb;
  bb.set("state", 7);
  const std::string m = message_of([&] { (void)bb.get<double>("state"); });
  EXPECT_NE(m.find("'state'"), std::string::npos) << m;
  EXPECT_NE(m.find("int"), std::string::npos) << m;
  EXPECT_NE(m.find("double"), std::string::npos) << m;
  EXPECT_THROW((void)bb.find<double>("state"), BlackboardError);
}

TEST(Blackboard, WrongTypeOnSetIsAnErrorAndKeepsTheValue) {
  Blackboard bb;
  bb.set<std::string>("name", "o1");
  const std::string m = message_of([&] { bb.set("name", 1.5); });
  EXPECT_NE(m.find("std::string"), std::string::npos) << m;
  EXPECT_EQ(bb.get<std::string>("name"), "o1");
  EXPECT_EQ(bb.type_of("name"), "std::string");
}

TEST(Blackboard, MissingKey) {
  Blackboard bb;
  const std::string m = message_of([&] { (void)bb.get<int>("nope"); });
  EXPECT_NE(m.find("no key 'nope'"), std::string::npos) << m;
  EXPECT_EQ(bb.find<int>("nope"), nullptr);
  EXPECT_FALSE(bb.contains("nope"));
  EXPECT_FALSE(bb.erase("nope"));
  EXPECT_THROW((void)bb.type_of("nope"), rtamp::Error);
}

TEST(Blackboard, EntryHandlesReadAndWriteWithoutLookups) {
  Blackboard bb;
  auto e = bb.entry<int>("count", 10);
  EXPECT_TRUE(static_cast<bool>(e));
  EXPECT_EQ(e.get(), 10);
  e.set(11);
  EXPECT_EQ(bb.get<int>("count"), 11);
  bb.set("count", 12);
  EXPECT_EQ(e.get(), 12);
  auto again = bb.entry<int>("count", 0);
  EXPECT_EQ(again.get(), 12) << "an existing entry keeps its value";
  EXPECT_THROW(bb.entry<double>("count"), BlackboardError);
  EXPECT_TRUE(bb.erase("count"));
  EXPECT_FALSE(bb.contains("count"));
}

}  // namespace
}  // namespace rtamp::bt
