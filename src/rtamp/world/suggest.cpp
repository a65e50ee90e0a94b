#include "rtamp/world/suggest.hpp"

#include <algorithm>
#include <cstdlib>

namespace rtamp::world {

std::string quoted(std::string_view word) {
  std::string out;
  out.reserve(word.size() + 2);
  out += '\'';
  out += word;
  out += '\'';
  return out;
}

int edit_distance(std::string_view a, std::string_view b, int cap) {
  const int n = static_cast<int>(a.size()), m = static_cast<int>(b.size());
  if (std::abs(n - m) > cap) return cap + 1;
  std::vector<int> prev(m + 1), cur(m + 1);
  for (int j = 0; j <= m; ++j) prev[j] = j;
  for (int i = 1; i <= n; ++i) {
    cur[0] = i;
    int row_min = cur[0];
    for (int j = 1; j <= m; ++j) {
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
      row_min = std::min(row_min, cur[j]);
    }
    if (row_min > cap) return cap + 1;
    std::swap(prev, cur);
  }
  return std::min(prev[m], cap + 1);
}

std::string suggestion(std::string_view word, const std::vector<std::string>& candidates) {
  if (candidates.empty()) return "";
  const int limit = word.size() <= 3 ? 1 : 2;
  const std::string* best = nullptr;
  int best_d = limit + 1;
  for (const std::string& c : candidates) {
    const int d = edit_distance(word, c, limit);
    if (d < best_d) {
      best_d = d;
      best = &c;
    }
  }
  if (best && best_d > 0) return " (did you mean '" + *best + "'?)";
  std::string out = " (expected one of: ";
  const std::size_t shown = std::min<std::size_t>(candidates.size(), 12);
  for (std::size_t i = 0; i < shown; ++i) {
    if (i) out += ", ";
    out += candidates[i];
  }
  if (shown < candidates.size()) out += ", ...";
  return out + ")";
}

}  // namespace rtamp::world
