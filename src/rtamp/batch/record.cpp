#include "rtamp/batch/record.hpp"

#include <algorithm>
#include <tuple>

#include "rtamp/batch/trials.hpp"

namespace rtamp::batch {

std::string describe_key(const EpisodeRecord& r) {
  return "scenario " + r.scenario + ", " + r.algorithm + ", " + r.bt + ", " + r.change + ", trial " +
         std::to_string(r.trial);
}

bool canonical_less(const EpisodeRecord& a, const EpisodeRecord& b) {
  auto k = [](const EpisodeRecord& r) {
    return std::tuple<const std::string&, int, const std::string&, int, const std::string&, int,
                      const std::string&, int>(r.scenario, change_rank(r.change), r.change,
                                               algorithm_rank(r.algorithm), r.algorithm, bt_rank(r.bt), r.bt,
                                               r.trial);
  };
  return k(a) < k(b);
}

void sort_canonical(std::vector<EpisodeRecord>& records) {
  std::stable_sort(records.begin(), records.end(), canonical_less);
}

}  // namespace rtamp::batch
