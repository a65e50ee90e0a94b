#include "rtamp/batch/csv.hpp"

#include <sstream>

#include "rtamp/util/output_file.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <iterator>
#include <ostream>
#include <sstream>

#include "rtamp/batch/trials.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/text_file.hpp"

namespace rtamp::batch {

namespace {

enum Col {
  kScenario,
  kAlgorithm,
  kBt,
  kChange,
  kTrial,
  kSeed,
  kSuccess,
  kReason,
  kFirstPlan,
  kReplan,
  kReplans,
  kTreeChanges,
  kCompletion,
  kMotionCost,
  kInterventions,
  kWall,
  kRtf,
  kNumCols
};

std::string num(double v) {
  char buf[64];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, p) : std::string("nan");
}

template <typename I>
std::string num_int(I v) {
  char buf[32];
  const auto [p, ec] = std::to_chars(buf, buf + sizeof buf, v);
  (void)ec;
  return std::string(buf, p);
}

struct FieldContext {
  const std::string& file;
  int line;
  const std::string& column;
};

[[noreturn]] void bad_field(const FieldContext& c, const std::string& value, const std::string& expected) {
  throw Error("bad value '" + value + "' in column '" + c.column + "' (expected " + expected + ")",
              SourceLocation{c.file, c.line, 0});
}

double parse_double(const std::string& s, const FieldContext& c) {
  double v = 0;
  const char* b = s.data();
  const char* e = s.data() + s.size();
  const auto [p, ec] = std::from_chars(b, e, v);
  if (s.empty() || ec != std::errc() || p != e || !std::isfinite(v)) bad_field(c, s, "a finite number");
  return v;
}

template <typename I>
I parse_integer(const std::string& s, const FieldContext& c, I min_value) {
  I v = 0;
  const char* b = s.data();
  const char* e = s.data() + s.size();
  const auto [p, ec] = std::from_chars(b, e, v);
  if (s.empty() || ec != std::errc() || p != e || v < min_value)
    bad_field(c, s, "an integer >= " + num_int(min_value));
  return v;
}

bool parse_bool(const std::string& s, const FieldContext& c) {
  if (s == "1" || s == "true") return true;
  if (s == "0" || s == "false") return false;
  bad_field(c, s, "1 or 0");
}

}  // namespace

const std::vector<std::string>& csv_columns() {
  static const std::vector<std::string> cols = {
      "scenario",     "algorithm", "bt",      "change",       "trial",       "seed",
      "success",      "reason",    "first_plan_s", "replan_s", "replans",     "tree_changes",
      "completion_s", "motion_cost", "interventions", "wall_s", "rtf"};
  return cols;
}

std::string csv_quote(const std::string& f) {
  const bool needs = f.find_first_of(",\"\r\n") != std::string::npos ||
                     (!f.empty() && (f.front() == ' ' || f.front() == '\t' || f.back() == ' ' || f.back() == '\t'));
  if (!needs) return f;
  std::string out = "\"";
  for (char ch : f) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
  return out;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string out;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    out += csv_quote(fields[i]);
  }
  return out;
}

CsvRows parse_csv(const std::string& text, const std::string& file) {
  CsvRows out;
  std::vector<std::string> row;
  std::string field;
  int line = 1, col = 1;
  int row_line = 1;
  bool in_row = false;  // something of the current row has been read
  std::size_t i = 0;
  const std::size_t n = text.size();
  auto end_field = [&] {
    row.push_back(std::move(field));
    field.clear();
  };
  auto end_row = [&] {
    end_field();
    out.rows.push_back(std::move(row));
    out.lines.push_back(row_line);
    row.clear();
    in_row = false;
  };
  while (i < n) {
    if (!in_row) {
      row_line = line;
      in_row = true;
    }
    const char ch = text[i];
    if (ch == '"' && field.empty()) {
      // Quoted field; it must start right after a separator or at the row start.
      const bool at_start = i == 0 || text[i - 1] == ',' || text[i - 1] == '\n' || text[i - 1] == '\r';
      if (!at_start) throw Error("stray double quote inside an unquoted field", SourceLocation{file, line, col});
      const int qline = line, qcol = col;
      ++i, ++col;
      for (;;) {
        if (i >= n) throw Error("unterminated quoted field", SourceLocation{file, qline, qcol});
        if (text[i] == '"') {
          if (i + 1 < n && text[i + 1] == '"') {
            field += '"';
            i += 2, col += 2;
            continue;
          }
          ++i, ++col;
          break;
        }
        if (text[i] == '\n') ++line, col = 0;
        field += text[i];
        ++i, ++col;
      }
      if (i < n && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
        throw Error("text after the closing quote of a field", SourceLocation{file, line, col});
      continue;
    }
    if (ch == '"') throw Error("stray double quote inside an unquoted field", SourceLocation{file, line, col});
    if (ch == ',') {
      end_field();
      ++i, ++col;
      continue;
    }
    if (ch == '\r' || ch == '\n') {
      end_row();
      if (ch == '\r' && i + 1 < n && text[i + 1] == '\n') ++i;
      ++i;
      ++line, col = 1;
      continue;
    }
    field += ch;
    ++i, ++col;
  }
  if (in_row) end_row();
  return out;
}

void write_header(std::ostream& out) { out << csv_line(csv_columns()) << '\n'; }

void write_record(std::ostream& out, const EpisodeRecord& r) {
  std::vector<std::string> f(kNumCols);
  f[kScenario] = r.scenario;
  f[kAlgorithm] = r.algorithm;
  f[kBt] = r.bt;
  f[kChange] = r.change;
  f[kTrial] = num_int(r.trial);
  f[kSeed] = num_int(r.seed);
  f[kSuccess] = r.success ? "1" : "0";
  f[kReason] = r.reason;
  f[kFirstPlan] = num(r.first_plan_s);
  f[kReplan] = num(r.replan_s);
  f[kReplans] = num_int(r.replans);
  f[kTreeChanges] = num_int(r.tree_changes);
  f[kCompletion] = num(r.completion_s);
  f[kMotionCost] = num(r.motion_cost);
  f[kInterventions] = num_int(r.interventions);
  f[kWall] = num(r.wall_s);
  f[kRtf] = num(r.rtf);
  out << csv_line(f) << '\n';
}

void write_csv(std::ostream& out, const std::vector<EpisodeRecord>& records) {
  write_header(out);
  for (const auto& r : records) write_record(out, r);
}

void write_csv_file(const std::string& path, const std::vector<EpisodeRecord>& records, const std::string& what) {
  std::ostringstream text;
  write_csv(text, records);
  write_output_file(path, what, text.str());
}

std::vector<EpisodeRecord> read_csv(const std::string& text, const std::string& file) {
  const CsvRows rows = parse_csv(text, file);
  if (rows.rows.empty()) throw Error("empty CSV file (no header)", SourceLocation{file, 1, 0});
  const auto& cols = csv_columns();
  const auto& header = rows.rows.front();
  if (header != cols) {
    std::size_t i = 0;
    while (i < header.size() && i < cols.size() && header[i] == cols[i]) ++i;
    std::string detail = "expected header: " + csv_line(cols);
    std::string what = i < header.size() && i < cols.size()
                           ? "unexpected header: column " + std::to_string(i + 1) + " is '" + header[i] +
                                 "', expected '" + cols[i] + "'"
                           : "unexpected header: " + std::to_string(header.size()) + " columns, expected " +
                                 std::to_string(cols.size());
    throw Error(what, SourceLocation{file, rows.lines.front(), 0}, detail);
  }
  std::vector<EpisodeRecord> out;
  out.reserve(rows.rows.size() - 1);
  for (std::size_t ri = 1; ri < rows.rows.size(); ++ri) {
    const auto& f = rows.rows[ri];
    const int line = rows.lines[ri];
    if (f.size() == 1 && f[0].empty()) continue;  // blank line
    if (f.size() != cols.size())
      throw Error("row has " + std::to_string(f.size()) + " fields, expected " + std::to_string(cols.size()),
                  SourceLocation{file, line, 0});
    auto ctx = [&](Col c) { return FieldContext{file, line, cols[c]}; };
    EpisodeRecord r;
    r.scenario = f[kScenario];
    if (r.scenario.empty()) bad_field(ctx(kScenario), "", "a scenario name");
    r.algorithm = f[kAlgorithm];
    r.bt = f[kBt];
    r.change = f[kChange];
    try {
      plan::parse_algorithm(r.algorithm);
      parse_bt_variant(r.bt);
      parse_change_kind(r.change);
    } catch (const Error& e) {
      throw Error(e.message(), SourceLocation{file, line, 0});
    }
    r.trial = parse_integer<int>(f[kTrial], ctx(kTrial), 1);
    r.seed = parse_integer<std::uint64_t>(f[kSeed], ctx(kSeed), 0);
    r.success = parse_bool(f[kSuccess], ctx(kSuccess));
    r.reason = f[kReason];
    r.first_plan_s = parse_double(f[kFirstPlan], ctx(kFirstPlan));
    r.replan_s = parse_double(f[kReplan], ctx(kReplan));
    r.replans = parse_integer<int>(f[kReplans], ctx(kReplans), 0);
    r.tree_changes = parse_integer<std::uint64_t>(f[kTreeChanges], ctx(kTreeChanges), 0);
    r.completion_s = parse_double(f[kCompletion], ctx(kCompletion));
    r.motion_cost = parse_double(f[kMotionCost], ctx(kMotionCost));
    r.interventions = parse_integer<int>(f[kInterventions], ctx(kInterventions), 0);
    r.wall_s = parse_double(f[kWall], ctx(kWall));
    r.rtf = parse_double(f[kRtf], ctx(kRtf));
    out.push_back(std::move(r));
  }
  return out;
}

std::vector<EpisodeRecord> read_csv_file(const std::string& path) {
  return read_csv(read_text_file(path, "the CSV file", kMaxCsvBytes), path);
}

}  // namespace rtamp::batch
