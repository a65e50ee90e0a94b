// Resuming an interrupted batch (`rtamp batch --resume`): the CSV a killed or
// interrupted batch left behind (rows are appended as episodes finish) is
// read back, its whole rows kept and the trials they ran taken off the list;
// only the missing trials run again.
// Rules: a torn last line (the file does not end with a line end) is dropped;
// the rest must be this version's CSV (csv.hpp) of this very batch — each
// row's (algorithm, bt, change, trial) in the trial list with the same seed and
// scenario, no row twice — or the resume is refused (rtamp::Error at the row's
// line) before anything runs or the file is changed. An empty file is a batch
// that had not started.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "rtamp/batch/record.hpp"
#include "rtamp/batch/trials.hpp"

namespace rtamp::batch {

struct Resumed {
  std::vector<EpisodeRecord> kept;  // the whole rows, in the file's order
  std::vector<Trial> missing;       // the trials still to run, in the list's order
  std::size_t whole_bytes = 0;      // the length of the file's whole lines (a torn line after them)
  bool has_header = false;          // the kept text starts with the header
};

// `text`: the CSV's contents; `file` names it in errors.
Resumed resume(const std::string& text, const std::string& file, const std::string& scenario,
               const std::vector<Trial>& trials);

}  // namespace rtamp::batch
