#include "rtamp/batch/resume.hpp"

#include <map>
#include <tuple>

#include "rtamp/batch/csv.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::batch {

Resumed resume(const std::string& text, const std::string& file, const std::string& scenario,
               const std::vector<Trial>& trials) {
  Resumed out;
  const std::size_t end = text.rfind('\n');
  out.whole_bytes = end == std::string::npos ? 0 : end + 1;
  const std::string whole = text.substr(0, out.whole_bytes);
  if (whole.find_first_not_of(" \t\r\n") == std::string::npos) {  // nothing ran (or a torn header)
    out.whole_bytes = 0;
    out.missing = trials;
    return out;
  }
  out.has_header = true;
  using Key = std::tuple<std::string, std::string, std::string, int>;  // algorithm, bt, change, trial
  std::map<Key, std::size_t> index;                                    // into trials
  for (std::size_t i = 0; i < trials.size(); ++i) {
    const Trial& t = trials[i];
    index[{plan::to_string(t.algorithm), to_string(t.bt), to_string(t.change), t.index}] = i;
  }
  std::vector<bool> done(trials.size(), false);
  const CsvRows rows = parse_csv(whole, file);
  std::vector<EpisodeRecord> records = read_csv(whole, file);
  // read_csv skips blank lines: pair records with their lines again.
  std::vector<int> lines;
  for (std::size_t r = 1; r < rows.rows.size(); ++r)
    if (!(rows.rows[r].size() == 1 && rows.rows[r][0].empty())) lines.push_back(rows.lines[r]);
  for (std::size_t k = 0; k < records.size(); ++k) {
    const EpisodeRecord& r = records[k];
    const SourceLocation at{file, k < lines.size() ? lines[k] : 0, 0};
    if (r.scenario != scenario)
      throw Error("--resume: a row of scenario '" + r.scenario + "', not '" + scenario +
                      "' (resume a batch with the options it was started with)",
                  at);
    auto it = index.find({r.algorithm, r.bt, r.change, r.trial});
    if (it == index.end())
      throw Error("--resume: the row (" + describe_key(r) +
                      ") is not a trial of this batch (resume a batch with the options it was started with)",
                  at);
    if (trials[it->second].seed != r.seed)
      throw Error("--resume: the row (" + describe_key(r) + ") has seed " + std::to_string(r.seed) +
                      ", this batch's trial has seed " + std::to_string(trials[it->second].seed) +
                      " (another --seed)",
                  at);
    if (done[it->second]) throw Error("--resume: the row (" + describe_key(r) + ") is there twice", at);
    done[it->second] = true;
    out.kept.push_back(r);
  }
  for (std::size_t i = 0; i < trials.size(); ++i)
    if (!done[i]) out.missing.push_back(trials[i]);
  return out;
}

}  // namespace rtamp::batch
