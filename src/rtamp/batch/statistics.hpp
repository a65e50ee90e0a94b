// Descriptive statistics of a batch metric, as reported in the paper's
// Table I: mean ± half-width of the 95% confidence interval of the mean, and
// the median.
//
// The confidence interval is Student's t interval: mean ± t(0.975, n-1)·s/√n,
// with s the sample standard deviation (divisor n-1). t(0.975, df) comes from
// a table: exact to 4 decimals for df = 1..30, 40, 60, 120; between 30 and 120
// it is interpolated linearly in 1/df (error < 5e-4), beyond 120 interpolated
// between t(120) and the normal quantile 1.95996 (df = ∞). Values:
// t_critical_95(). With n < 2 the interval is undefined (ci95 is NaN); with
// n == 0 mean and median are NaN too. Non-finite samples are not accepted by
// the callers (the CSV reader rejects them).
#pragma once

#include <cstddef>
#include <span>

namespace rtamp::batch {

struct Stats {
  std::size_t n = 0;
  double mean = 0;
  double stddev = 0;  // sample standard deviation (n-1); NaN if n < 2
  double ci95 = 0;    // half-width of the 95% CI of the mean; NaN if n < 2
  double median = 0;  // middle value, or mean of the two middle values
  double min = 0, max = 0;
};

// Two-sided 95% critical value of Student's t with `df` degrees of freedom (df >= 1).
double t_critical_95(std::size_t df);

Stats describe(std::span<const double> samples);

}  // namespace rtamp::batch
