// The summary of a batch — the paper's Table I (Section VI): one row per
// cell (by default change kind × algorithm × BT variant, per scenario) with
//   Success n/N · Init plan time · Total replan time · # replan (mean, median)
//   · Tree changes · Completion time
// where times are mean ± half-width of the 95% confidence interval
// (statistics.hpp: Student t). The data behind Fig. 4 (completion time and
// tree changes per BT variant) is the same table grouped by scenario × BT
// variant (Grouping).
//
// What is averaged: completion time over the successful episodes of the cell
// only (a failed episode has no completion time); every other metric over all
// episodes of the cell. Rows come in canonical order (record.hpp). Renderings:
// a fixed-width terminal table, Markdown (docs/benchmarks.md), JSON (every
// statistic of every metric; NaN → null) and TSV (for gnuplot:
// scripts/plot-results). In the text and Markdown tables, a key that has a
// single value over all rows is named in the title instead of a column.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rtamp/batch/record.hpp"
#include "rtamp/batch/statistics.hpp"

namespace rtamp::batch {

// Which keys define a cell; keys not grouped by are pooled (shown as "*").
struct Grouping {
  bool scenario = true, change = true, algorithm = true, bt = true;
};
// "scenario,change,algorithm,bt" or any subset (order irrelevant); throws rtamp::Error.
Grouping parse_grouping(std::string_view text);

struct SummaryRow {
  std::string scenario, change, algorithm, bt;  // "*" when pooled
  std::size_t trials = 0, successes = 0;
  Stats first_plan_s, replan_s, replans, tree_changes, completion_s, motion_cost, wall_s;
};

struct Summary {
  Grouping grouping;
  std::vector<SummaryRow> rows;
  std::size_t episodes = 0;
  double wall_s = 0;  // sum of episode wall times
};

Summary summarize(const std::vector<EpisodeRecord>& records, Grouping grouping = {});

// "466.50 ± 34.80": decimals chosen so the CI half-width shows 2 significant
// digits (at least 2, at most 6 decimals); "12.30" when the CI is undefined;
// "—" when there is no sample.
std::string mean_ci(const Stats& s);
// "0.80, 0": mean and median as in the paper's "# replan" column.
std::string mean_median(const Stats& s);

std::string format_text(const Summary& s);
std::string format_markdown(const Summary& s);
// JSON text (nlohmann::json::dump(indent): -1 compact, >= 0 pretty with that indent).
std::string to_json(const Summary& s, int indent = -1);
std::string format_tsv(const Summary& s);

}  // namespace rtamp::batch
