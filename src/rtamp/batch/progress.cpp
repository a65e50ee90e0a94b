#include "rtamp/batch/progress.hpp"

#include <cmath>
#include <cstdio>

namespace rtamp::batch {

std::string format_duration(double s) {
  char buf[48];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 10) {
    std::snprintf(buf, sizeof buf, "%.1fs", s);
  } else if (s < 60) {
    std::snprintf(buf, sizeof buf, "%.0fs", std::floor(s));
  } else if (s < 3600) {
    const long t = static_cast<long>(s);
    std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  } else {
    const long t = static_cast<long>(s);
    std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t % 3600) / 60);
  }
  return buf;
}

double eta_seconds(const Progress& p) {
  if (p.done == 0 || p.total < p.done) return -1;
  return p.elapsed_s / static_cast<double>(p.done) * static_cast<double>(p.total - p.done);
}

std::string progress_bar(const Progress& p, int width) {
  const double frac = p.total ? static_cast<double>(p.done) / static_cast<double>(p.total) : 1.0;
  const int filled = static_cast<int>(std::floor(frac * width + 1e-9));
  std::string bar = "[";
  for (int i = 0; i < width; ++i) bar += i < filled ? '#' : '.';
  bar += "] " + std::to_string(p.done) + "/" + std::to_string(p.total) + "  elapsed " +
         format_duration(p.elapsed_s);
  const double eta = eta_seconds(p);
  bar += "  ETA " + (eta < 0 ? std::string("?") : format_duration(eta));
  bar += "  failures " + std::to_string(p.failures);
  return bar;
}

}  // namespace rtamp::batch
