#include "rtamp/batch/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "rtamp/util/error.hpp"

namespace rtamp::batch {

namespace {

std::size_t display_width(const std::string& s) {
  std::size_t w = 0;
  for (unsigned char c : s)
    if ((c & 0xC0) != 0x80) ++w;  // count UTF-8 lead bytes only
  return w;
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

int decimals_for(double x) {
  if (!std::isfinite(x) || x == 0) return 2;
  const int d = 1 - static_cast<int>(std::floor(std::log10(std::fabs(x))));
  return std::clamp(d, 2, 6);
}

Stats stats_of(const std::vector<const EpisodeRecord*>& rs, double EpisodeRecord::*field, bool successes_only) {
  std::vector<double> v;
  for (const auto* r : rs)
    if (!successes_only || r->success) v.push_back(r->*field);
  return describe(v);
}

template <typename I>
Stats stats_of_int(const std::vector<const EpisodeRecord*>& rs, I EpisodeRecord::*field) {
  std::vector<double> v;
  for (const auto* r : rs) v.push_back(static_cast<double>(r->*field));
  return describe(v);
}

struct Table {
  std::vector<std::string> header;
  std::vector<bool> right;                  // right-align this column
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> rule_before;            // a separator before this row
};

// Which key columns to show and the title naming the single-valued keys.
struct Layout {
  bool scenario = false, change = false, algorithm = false, bt = false;
  std::string title;
};

Layout layout_of(const Summary& s) {
  auto distinct = [&](std::string SummaryRow::*f) {
    std::set<std::string> v;
    for (const auto& r : s.rows) v.insert(r.*f);
    return v;
  };
  Layout l;
  std::vector<std::string> fixed_keys;
  auto decide = [&](bool grouped, std::string SummaryRow::*f, bool& show, const char* name) {
    const auto v = distinct(f);
    if (v.size() > 1) {
      show = true;
    } else if (v.size() == 1) {
      const std::string& only = *v.begin();
      fixed_keys.push_back(grouped && only != "*" ? only : std::string("all ") + name);
    }
  };
  decide(s.grouping.scenario, &SummaryRow::scenario, l.scenario, "scenarios");
  decide(s.grouping.change, &SummaryRow::change, l.change, "changes");
  decide(s.grouping.algorithm, &SummaryRow::algorithm, l.algorithm, "algorithms");
  decide(s.grouping.bt, &SummaryRow::bt, l.bt, "BT variants");
  for (std::size_t i = 0; i < fixed_keys.size(); ++i) l.title += (i ? ", " : "") + fixed_keys[i];
  return l;
}

Table make_table(const Summary& s, const Layout& l) {
  Table t;
  auto col = [&](const char* h, bool right) {
    t.header.push_back(h);
    t.right.push_back(right);
  };
  if (l.scenario) col("Scenario", false);
  if (l.change) col("Change", false);
  if (l.algorithm) col("Algorithm", false);
  if (l.bt) col("BT", false);
  col("Success", true);
  col("Init plan time (s)", true);
  col("Total replan time (s)", true);
  col("# replan (mean, median)", true);
  col("Tree changes", true);
  col("Completion time (s)", true);
  const SummaryRow* prev = nullptr;
  for (const auto& r : s.rows) {
    std::vector<std::string> cells;
    if (l.scenario) cells.push_back(r.scenario);
    if (l.change) cells.push_back(r.change);
    if (l.algorithm) cells.push_back(r.algorithm);
    if (l.bt) cells.push_back(r.bt);
    cells.push_back(std::to_string(r.successes) + "/" + std::to_string(r.trials));
    cells.push_back(mean_ci(r.first_plan_s));
    cells.push_back(mean_ci(r.replan_s));
    cells.push_back(mean_median(r.replans));
    cells.push_back(mean_ci(r.tree_changes));
    cells.push_back(mean_ci(r.completion_s));
    t.rule_before.push_back(prev && ((l.scenario && prev->scenario != r.scenario) ||
                                     (l.change && prev->change != r.change)));
    t.rows.push_back(std::move(cells));
    prev = &r;
  }
  return t;
}

std::string pad(const std::string& s, std::size_t w, bool right) {
  const std::size_t n = display_width(s);
  const std::string sp(w > n ? w - n : 0, ' ');
  return right ? sp + s : s + sp;
}

std::string footnote(const Summary& s) {
  std::ostringstream o;
  o << s.episodes << " episodes; mean ± 95% confidence interval (Student t); completion time over successful "
                     "episodes only";
  return o.str();
}

nlohmann::json stats_json(const Stats& st) {
  auto num = [](double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); };
  return {{"n", st.n},           {"mean", num(st.mean)}, {"ci95", num(st.ci95)}, {"median", num(st.median)},
          {"stddev", num(st.stddev)}, {"min", num(st.min)},   {"max", num(st.max)}};
}

}  // namespace

Grouping parse_grouping(std::string_view text) {
  Grouping g{false, false, false, false};
  std::size_t pos = 0;
  while (pos <= text.size()) {
    const std::size_t comma = std::min(text.find(',', pos), text.size());
    const std::string_view k = text.substr(pos, comma - pos);
    if (k == "scenario") g.scenario = true;
    else if (k == "change") g.change = true;
    else if (k == "algorithm" || k == "algo") g.algorithm = true;
    else if (k == "bt") g.bt = true;
    else
      throw Error("unknown grouping key '" + std::string(k) + "' in '" + std::string(text) +
                  "' (expected a comma-separated subset of scenario, change, algorithm, bt)");
    pos = comma + 1;
  }
  return g;
}

Summary summarize(const std::vector<EpisodeRecord>& records, Grouping grouping) {
  Summary s;
  s.grouping = grouping;
  s.episodes = records.size();
  // Group on a representative record whose pooled keys are "*".
  std::vector<std::pair<EpisodeRecord, std::vector<const EpisodeRecord*>>> groups;
  std::map<std::tuple<std::string, std::string, std::string, std::string>, std::size_t> index;
  for (const auto& r : records) {
    s.wall_s += r.wall_s;
    EpisodeRecord key;
    key.scenario = grouping.scenario ? r.scenario : "*";
    key.change = grouping.change ? r.change : "*";
    key.algorithm = grouping.algorithm ? r.algorithm : "*";
    key.bt = grouping.bt ? r.bt : "*";
    key.trial = 0;
    auto [it, fresh] = index.emplace(std::make_tuple(key.scenario, key.change, key.algorithm, key.bt), groups.size());
    if (fresh) groups.push_back({key, {}});
    groups[it->second].second.push_back(&r);
  }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const auto& a, const auto& b) { return canonical_less(a.first, b.first); });
  for (const auto& [key, rs] : groups) {
    SummaryRow row;
    row.scenario = key.scenario;
    row.change = key.change;
    row.algorithm = key.algorithm;
    row.bt = key.bt;
    row.trials = rs.size();
    for (const auto* r : rs) row.successes += r->success ? 1 : 0;
    row.first_plan_s = stats_of(rs, &EpisodeRecord::first_plan_s, false);
    row.replan_s = stats_of(rs, &EpisodeRecord::replan_s, false);
    row.replans = stats_of_int(rs, &EpisodeRecord::replans);
    row.tree_changes = stats_of_int(rs, &EpisodeRecord::tree_changes);
    row.completion_s = stats_of(rs, &EpisodeRecord::completion_s, true);
    row.motion_cost = stats_of(rs, &EpisodeRecord::motion_cost, false);
    row.wall_s = stats_of(rs, &EpisodeRecord::wall_s, false);
    s.rows.push_back(std::move(row));
  }
  return s;
}

std::string mean_ci(const Stats& s) {
  if (s.n == 0 || !std::isfinite(s.mean)) return "—";
  if (!std::isfinite(s.ci95)) return fixed(s.mean, decimals_for(s.mean));
  const int d = s.ci95 > 0 ? decimals_for(s.ci95) : decimals_for(s.mean);
  return fixed(s.mean, d) + " ± " + fixed(s.ci95, d);
}

std::string mean_median(const Stats& s) {
  if (s.n == 0 || !std::isfinite(s.mean)) return "—";
  // The median of integers is an integer or a half.
  const bool whole = s.median == std::floor(s.median);
  return fixed(s.mean, 2) + ", " + fixed(s.median, whole ? 0 : 1);
}

std::string format_text(const Summary& s) {
  const Layout l = layout_of(s);
  const Table t = make_table(s, l);
  std::vector<std::size_t> w(t.header.size());
  for (std::size_t c = 0; c < w.size(); ++c) {
    w[c] = display_width(t.header[c]);
    for (const auto& r : t.rows) w[c] = std::max(w[c], display_width(r[c]));
  }
  std::size_t total = 0;
  for (auto x : w) total += x;
  total += 2 * (w.size() - 1);
  std::ostringstream o;
  if (!l.title.empty()) o << l.title << "\n";
  auto line = [&](const std::vector<std::string>& cells) {
    std::string out;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      if (c) out += "  ";
      out += pad(cells[c], w[c], t.right[c]);
    }
    while (!out.empty() && out.back() == ' ') out.pop_back();
    o << out << "\n";
  };
  std::string rule;
  for (std::size_t i = 0; i < total; ++i) rule += "─";
  line(t.header);
  o << rule << "\n";
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (t.rule_before[i]) o << rule << "\n";
    line(t.rows[i]);
  }
  o << footnote(s) << "\n";
  return o.str();
}

std::string format_markdown(const Summary& s) {
  const Layout l = layout_of(s);
  const Table t = make_table(s, l);
  std::ostringstream o;
  if (!l.title.empty()) o << "**" << l.title << "**\n\n";
  auto line = [&](const std::vector<std::string>& cells) {
    o << "|";
    for (const auto& c : cells) {
      std::string esc;
      for (char ch : c) esc += ch == '|' ? std::string("\\|") : std::string(1, ch);
      o << " " << esc << " |";
    }
    o << "\n";
  };
  line(t.header);
  o << "|";
  for (std::size_t c = 0; c < t.header.size(); ++c) o << (t.right[c] ? " ---: |" : " --- |");
  o << "\n";
  for (const auto& r : t.rows) line(r);
  o << "\n" << footnote(s) << ".\n";
  return o.str();
}

std::string to_json(const Summary& s, int indent) {
  nlohmann::json rows = nlohmann::json::array();
  for (const auto& r : s.rows) {
    rows.push_back({{"scenario", r.scenario},
                    {"change", r.change},
                    {"algorithm", r.algorithm},
                    {"bt", r.bt},
                    {"trials", r.trials},
                    {"successes", r.successes},
                    {"first_plan_s", stats_json(r.first_plan_s)},
                    {"replan_s", stats_json(r.replan_s)},
                    {"replans", stats_json(r.replans)},
                    {"tree_changes", stats_json(r.tree_changes)},
                    {"completion_s", stats_json(r.completion_s)},
                    {"motion_cost", stats_json(r.motion_cost)},
                    {"wall_s", stats_json(r.wall_s)}});
  }
  const nlohmann::json j = {{"episodes", s.episodes},
                            {"episode_wall_s", s.wall_s},
                            {"confidence", "95% Student t interval of the mean (ci95 = half-width)"},
                            {"completion_over", "successful episodes"},
                            {"rows", rows}};
  return j.dump(indent);
}

std::string format_tsv(const Summary& s) {
  std::ostringstream o;
  o << "# scenario\tchange\talgorithm\tbt\ttrials\tsuccesses";
  const char* names[] = {"first_plan_s", "replan_s", "replans", "tree_changes", "completion_s", "motion_cost"};
  for (const char* n : names) o << "\t" << n << "_mean\t" << n << "_ci95\t" << n << "_median";
  o << "\n";
  auto num = [](double v) {
    if (!std::isfinite(v)) return std::string("NaN");
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return std::string(buf);
  };
  for (const auto& r : s.rows) {
    o << r.scenario << "\t" << r.change << "\t" << r.algorithm << "\t" << r.bt << "\t" << r.trials << "\t"
      << r.successes;
    for (const Stats* st : {&r.first_plan_s, &r.replan_s, &r.replans, &r.tree_changes, &r.completion_s,
                            &r.motion_cost})
      o << "\t" << num(st->mean) << "\t" << num(st->ci95) << "\t" << num(st->median);
    o << "\n";
  }
  return o.str();
}

}  // namespace rtamp::batch
