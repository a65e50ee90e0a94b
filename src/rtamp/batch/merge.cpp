#include "rtamp/batch/merge.hpp"

#include <iterator>
#include <map>
#include <tuple>

#include "rtamp/batch/csv.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/text_file.hpp"

namespace rtamp::batch {

std::vector<EpisodeRecord> merge_slices(const std::vector<CsvSource>& sources) {
  if (sources.empty()) throw Error("--merge needs at least one CSV file");
  std::vector<std::string> first_header;
  std::vector<EpisodeRecord> all;
  using Key = std::tuple<std::string, std::string, std::string, std::string, int>;
  std::map<Key, std::string> seen;                                            // key -> file
  std::map<std::pair<std::string, int>, std::pair<std::uint64_t, std::string>> seeds;  // (scenario, trial) -> seed, file
  for (std::size_t i = 0; i < sources.size(); ++i) {
    const auto& src = sources[i];
    const CsvRows rows = parse_csv(src.text, src.file);
    if (rows.rows.empty()) throw Error("empty CSV file (no header)", SourceLocation{src.file, 1, 0});
    if (i == 0) {
      first_header = rows.rows.front();
    } else if (rows.rows.front() != first_header) {
      throw Error("header differs from that of '" + sources.front().file + "'", SourceLocation{src.file, 1, 0},
                  "  " + sources.front().file + ": " + csv_line(first_header) + "\n  " + src.file + ": " +
                      csv_line(rows.rows.front()));
    }
    for (auto& r : read_csv(src.text, src.file)) {
      Key k{r.scenario, r.algorithm, r.bt, r.change, r.trial};
      auto [it, fresh] = seen.emplace(k, src.file);
      if (!fresh)
        throw Error("duplicate row (" + describe_key(r) + ") in '" + it->second + "'" +
                        (it->second == src.file ? "" : " and '" + src.file + "'") +
                        ": are two slices overlapping, or a file given twice?",
                    SourceLocation{src.file, 0, 0});
      auto [sit, sfresh] = seeds.emplace(std::make_pair(r.scenario, r.trial), std::make_pair(r.seed, src.file));
      if (!sfresh && sit->second.first != r.seed)
        throw Error("trial " + std::to_string(r.trial) + " of scenario " + r.scenario + " has seed " +
                        std::to_string(sit->second.first) + " in '" + sit->second.second + "' but seed " +
                        std::to_string(r.seed) + " in '" + src.file +
                        "': the slices were run with different --seed and are not paired",
                    SourceLocation{src.file, 0, 0});
      all.push_back(std::move(r));
    }
  }
  sort_canonical(all);
  return all;
}

std::vector<EpisodeRecord> merge_files(const std::vector<std::string>& paths) {
  std::vector<CsvSource> sources;
  for (const auto& p : paths) {
    sources.push_back({p, read_text_file(p, "the CSV file", kMaxCsvBytes)});
  }
  return merge_slices(sources);
}

}  // namespace rtamp::batch
