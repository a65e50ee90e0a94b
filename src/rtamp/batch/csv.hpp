// The per-episode CSV of `rtamp batch`: RFC 4180 text (comma separated,
// fields quoted when they hold a comma, a double quote, CR, LF or leading /
// trailing blanks, quotes doubled inside quotes; CRLF or LF line ends read),
// one header line then one row per episode with the columns of csv_columns():
//
//   scenario,algorithm,bt,change,trial,seed,success,reason,first_plan_s,
//   replan_s,replans,tree_changes,completion_s,motion_cost,interventions,
//   wall_s,rtf
//
// success is 1 or 0; real numbers are written in the shortest form that reads
// back to the same double (std::to_chars), so write → read is the identity.
// The reader rejects, with file:line:column, anything else: a different
// header, a row with the wrong number of fields, an unknown algorithm / BT
// variant / change kind, a malformed or non-finite number, a broken quote.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "rtamp/batch/record.hpp"

namespace rtamp::batch {

// The largest CSV file read (--merge, --resume): a million rows take about 200 MB.
inline constexpr std::size_t kMaxCsvBytes = std::size_t(1) << 30;

const std::vector<std::string>& csv_columns();

// One field, quoted if needed.
std::string csv_quote(const std::string& field);
// One line (without the line end) of quoted fields.
std::string csv_line(const std::vector<std::string>& fields);

// Generic RFC 4180 parse: rows of fields, with the 1-based line each row starts on.
struct CsvRows {
  std::vector<std::vector<std::string>> rows;
  std::vector<int> lines;
};
// Throws rtamp::Error with `file` and the line / column of a broken quote.
CsvRows parse_csv(const std::string& text, const std::string& file = {});

// Records as CSV text (header included), in the given order.
void write_header(std::ostream& out);
void write_record(std::ostream& out, const EpisodeRecord& r);
void write_csv(std::ostream& out, const std::vector<EpisodeRecord>& records);
// Writes to `path` as every output is written (util/output_file.hpp: locked,
// checked); throws rtamp::OutputError "WHAT: cannot write 'PATH': WHY" if it cannot.
void write_csv_file(const std::string& path, const std::vector<EpisodeRecord>& records,
                    const std::string& what = "--output");

// Parses CSV text written by write_csv (the header must be exactly
// csv_columns()). `file` is used in error messages only.
std::vector<EpisodeRecord> read_csv(const std::string& text, const std::string& file = {});
std::vector<EpisodeRecord> read_csv_file(const std::string& path);

}  // namespace rtamp::batch
