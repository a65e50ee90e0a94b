// Joining the CSV slices of a sharded batch (`rtamp batch --merge A.csv B.csv
// ...`): the slices of `--shard K/N` runs, possibly made on different
// machines, become one table as if the whole grid had been run at once.
//
// Checks (each failure is an rtamp::Error naming the files involved):
//  - every file has the same header as the first, and it is the header of
//    csv.hpp (a slice written by another version of rtamp is refused);
//  - no (scenario, algorithm, bt, change, trial) appears twice, within a file
//    or across files (a slice given twice, or overlapping shards);
//  - a trial number has one seed per scenario (slices run with different
//    --seed are not paired and are refused).
// The result is sorted canonically (record.hpp). Missing trials are not an
// error — a partial grid merges; the summary shows n/N per cell.
#pragma once

#include <string>
#include <vector>

#include "rtamp/batch/record.hpp"

namespace rtamp::batch {

struct CsvSource {
  std::string file;  // name used in messages
  std::string text;  // the file's contents
};

std::vector<EpisodeRecord> merge_slices(const std::vector<CsvSource>& sources);
// Reads the files, then merge_slices().
std::vector<EpisodeRecord> merge_files(const std::vector<std::string>& paths);

}  // namespace rtamp::batch
