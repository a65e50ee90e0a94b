// The helper thread against a plain loop: many jobs in turn each run exactly once, on
// another thread, and wait() returns only after the job's writes; a job still running
// when the helper is destroyed is finished first.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>
#include <vector>

#include "rtamp/sim/helper_thread.hpp"

namespace rtamp::sim {
namespace {

TEST(HelperThread, EachJobRunsOnceOnAnotherThreadBeforeWaitReturns) {
  HelperThread helper;
  std::vector<int> data(1000, 0);
  const std::thread::id caller = std::this_thread::get_id();
  int runs = 0, elsewhere = 0;
  for (int k = 1; k <= 500; ++k) {
    auto job = [&] {
      ++runs;
      elsewhere += std::this_thread::get_id() != caller;
      for (int& x : data) x += k;
    };
    helper.run(job);
    helper.wait();
    ASSERT_EQ(data.front(), k * (k + 1) / 2);
    ASSERT_EQ(data.back(), k * (k + 1) / 2);
  }
  EXPECT_EQ(runs, 500);
  EXPECT_EQ(elsewhere, 500);
}

TEST(HelperThread, TheDestructorFinishesARunningJob) {
  std::atomic<bool> finished{false};
  auto job = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    finished = true;
  };
  {
    HelperThread helper;
    helper.run(job);
  }
  EXPECT_TRUE(finished);
}

TEST(HelperThread, JoinWaitsAtTheEndOfItsScope) {
  HelperThread helper;
  std::atomic<bool> finished{false};
  auto job = [&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    finished = true;
  };
  helper.run(job);
  {
    const HelperThread::Join join(helper);
  }
  EXPECT_TRUE(finished);
}

}  // namespace
}  // namespace rtamp::sim
