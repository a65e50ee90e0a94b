// Statistics of a batch: hand-computed means, medians and t intervals, and the
// t table checked against a numerical integration of Student's t density.
#include "rtamp/batch/statistics.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

using rtamp::batch::describe;
using rtamp::batch::Stats;
using rtamp::batch::t_critical_95;

// P(T <= t) for Student's t with df degrees of freedom, by Simpson's rule on
// the density from 0 to t (the density is symmetric, so CDF = 0.5 + ∫0^t).
double t_cdf(double t, double df) {
  const double c = std::exp(std::lgamma((df + 1) / 2) - std::lgamma(df / 2)) / std::sqrt(df * std::numbers::pi);
  auto f = [&](double x) { return c * std::pow(1 + x * x / df, -(df + 1) / 2); };
  const int n = 20000;
  const double h = t / n;
  double s = f(0) + f(t);
  for (int i = 1; i < n; ++i) s += f(i * h) * (i % 2 ? 4 : 2);
  return 0.5 + s * h / 3;
}

TEST(Statistics, TTableMatchesTheDistribution) {
  // Tabulated values: 4 decimals, so the CDF at them is within ~1e-4 of 0.975.
  for (std::size_t df = 1; df <= 30; ++df) EXPECT_NEAR(t_cdf(t_critical_95(df), double(df)), 0.975, 1.5e-4) << df;
  // Interpolated values (1/df), also within the stated error.
  for (std::size_t df : {31u, 35u, 45u, 50u, 59u, 61u, 80u, 100u, 119u, 121u, 200u, 500u, 1000u, 100000u})
    EXPECT_NEAR(t_cdf(t_critical_95(df), double(df)), 0.975, 2e-4) << df;
  EXPECT_NEAR(t_critical_95(1u << 30), 1.95996, 1e-4);
  EXPECT_TRUE(std::isnan(t_critical_95(0)));
}

TEST(Statistics, TIsDecreasingInDf) {
  for (std::size_t df = 1; df < 2000; ++df) EXPECT_GE(t_critical_95(df), t_critical_95(df + 1)) << df;
}

TEST(Statistics, HandComputedSample) {
  // 2, 4, 4, 4, 5, 5, 7, 9: mean 5, sum of squares 32, s^2 = 32/7,
  // CI = t(7) * sqrt(32/7) / sqrt(8) = 2.3646 * 0.755929 = 1.78747...
  const std::vector<double> x = {4, 2, 9, 4, 5, 4, 7, 5};
  const Stats s = describe(x);
  EXPECT_EQ(s.n, 8u);
  EXPECT_DOUBLE_EQ(s.mean, 5.0);
  EXPECT_NEAR(s.stddev, std::sqrt(32.0 / 7.0), 1e-12);
  EXPECT_NEAR(s.ci95, 2.3646 * std::sqrt(32.0 / 7.0) / std::sqrt(8.0), 1e-12);
  EXPECT_NEAR(s.ci95, 1.78747, 1e-5);
  EXPECT_DOUBLE_EQ(s.median, 4.5);
  EXPECT_DOUBLE_EQ(s.min, 2);
  EXPECT_DOUBLE_EQ(s.max, 9);
}

TEST(Statistics, OddCountMedianAndTwoSamples) {
  const std::vector<double> odd = {3, 1, 2};
  EXPECT_DOUBLE_EQ(describe(odd).median, 2);
  // n = 2: df 1, t = 12.7062; s = |a-b|/sqrt 2; CI = 12.7062 * s / sqrt 2 = 12.7062 * |a-b| / 2.
  const std::vector<double> two = {1, 3};
  const Stats s = describe(two);
  EXPECT_DOUBLE_EQ(s.mean, 2);
  EXPECT_NEAR(s.ci95, 12.7062, 1e-12);
  EXPECT_DOUBLE_EQ(s.median, 2);
}

TEST(Statistics, DegenerateSamples) {
  const Stats empty = describe(std::vector<double>{});
  EXPECT_EQ(empty.n, 0u);
  EXPECT_TRUE(std::isnan(empty.mean));
  EXPECT_TRUE(std::isnan(empty.median));
  const Stats one = describe(std::vector<double>{42});
  EXPECT_DOUBLE_EQ(one.mean, 42);
  EXPECT_DOUBLE_EQ(one.median, 42);
  EXPECT_TRUE(std::isnan(one.ci95));
  const Stats same = describe(std::vector<double>{7, 7, 7, 7});
  EXPECT_DOUBLE_EQ(same.ci95, 0);
  EXPECT_DOUBLE_EQ(same.stddev, 0);
}

TEST(Statistics, ThirtySamplesAgainstDirectFormula) {
  std::vector<double> x;
  for (int i = 0; i < 30; ++i) x.push_back(400 + ((i * 37) % 61));
  double mean = 0;
  for (double v : x) mean += v;
  mean /= 30;
  double ss = 0;
  for (double v : x) ss += (v - mean) * (v - mean);
  const Stats s = describe(x);
  EXPECT_NEAR(s.mean, mean, 1e-9);
  EXPECT_NEAR(s.ci95, 2.0452 * std::sqrt(ss / 29) / std::sqrt(30.0), 1e-9);
}

}  // namespace
