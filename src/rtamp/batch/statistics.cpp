#include "rtamp/batch/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rtamp::batch {

namespace {

// t(0.975, df) for df = 1..30.
constexpr double kT[30] = {12.7062, 4.3027, 3.1824, 2.7764, 2.5706, 2.4469, 2.3646, 2.3060, 2.2622, 2.2281,
                           2.2010,  2.1788, 2.1604, 2.1448, 2.1314, 2.1199, 2.1098, 2.1009, 2.0930, 2.0860,
                           2.0796,  2.0739, 2.0687, 2.0639, 2.0595, 2.0555, 2.0518, 2.0484, 2.0452, 2.0423};
// Anchors above 30: (df, t); the last is df = ∞ (inverse 0).
constexpr double kAnchorDf[] = {30, 40, 60, 120};
constexpr double kAnchorT[] = {2.0423, 2.0211, 2.0003, 1.9799};
constexpr double kNormal = 1.95996;

}  // namespace

double t_critical_95(std::size_t df) {
  if (df == 0) return std::numeric_limits<double>::quiet_NaN();
  if (df <= 30) return kT[df - 1];
  const double inv = 1.0 / static_cast<double>(df);
  for (std::size_t i = 0; i + 1 < std::size(kAnchorDf); ++i) {
    if (static_cast<double>(df) <= kAnchorDf[i + 1]) {
      const double a = 1.0 / kAnchorDf[i], b = 1.0 / kAnchorDf[i + 1];
      const double w = (a - inv) / (a - b);
      return kAnchorT[i] + w * (kAnchorT[i + 1] - kAnchorT[i]);
    }
  }
  const double a = 1.0 / kAnchorDf[std::size(kAnchorDf) - 1];
  const double w = (a - inv) / a;  // 0 at df = 120, 1 at df = ∞
  return kAnchorT[std::size(kAnchorT) - 1] + w * (kNormal - kAnchorT[std::size(kAnchorT) - 1]);
}

Stats describe(std::span<const double> samples) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  Stats s;
  s.n = samples.size();
  if (s.n == 0) {
    s.mean = s.stddev = s.ci95 = s.median = s.min = s.max = nan;
    return s;
  }
  // Two-pass mean and variance (numerically stable for these sizes).
  double sum = 0;
  for (double x : samples) sum += x;
  s.mean = sum / static_cast<double>(s.n);
  std::vector<double> sorted(samples.begin(), samples.end());
  std::sort(sorted.begin(), sorted.end());
  s.min = sorted.front();
  s.max = sorted.back();
  const std::size_t mid = s.n / 2;
  s.median = s.n % 2 ? sorted[mid] : 0.5 * (sorted[mid - 1] + sorted[mid]);
  if (s.n < 2) {
    s.stddev = s.ci95 = nan;
    return s;
  }
  double ss = 0;
  for (double x : samples) ss += (x - s.mean) * (x - s.mean);
  s.stddev = std::sqrt(ss / static_cast<double>(s.n - 1));
  s.ci95 = t_critical_95(s.n - 1) * s.stddev / std::sqrt(static_cast<double>(s.n));
  return s;
}

}  // namespace rtamp::batch
