// Progress report of a running batch on stderr: a one-line bar redrawn in
// place when stderr is a terminal ("[#####.....] 12/270  elapsed 1m02s  ETA
// 20m10s  failures 0"), or one plain line per finished episode otherwise
// (logs of GNU parallel / Slurm jobs). Pure formatting: the caller measures
// time and decides where the text goes.
//
// ETA = elapsed / done × (total − done), blank until one episode is done.
#pragma once

#include <cstddef>
#include <string>

namespace rtamp::batch {

struct Progress {
  std::size_t done = 0, total = 0, failures = 0;
  double elapsed_s = 0;
};

// "1m02s", "2h03m", "45s", "0.3s".
std::string format_duration(double seconds);
// The bar line (no line end); `width` is the number of cells in the bar.
std::string progress_bar(const Progress& p, int width = 30);
// Estimated seconds left; negative if unknown (nothing done yet).
double eta_seconds(const Progress& p);

}  // namespace rtamp::batch
