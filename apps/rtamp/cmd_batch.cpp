// rtamp batch — seeded batches of episodes (batch/runner.hpp) and the summary
// table of the paper's Table I (batch/summary.hpp); `--shard K/N` runs one
// slice of the trial list, `--merge CSV...` joins slices (batch/merge.hpp).
// Options and output: docs/cli.md and docs/experiments.md.
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <csignal>
#include <sstream>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <thread>

#include "command.hpp"
#include "episode_args.hpp"
#include "options.hpp"
#include "rtamp/batch/csv.hpp"
#include "rtamp/batch/merge.hpp"
#include "rtamp/batch/progress.hpp"
#include "rtamp/batch/runner.hpp"
#include "rtamp/batch/summary.hpp"
#include "rtamp/batch/trials.hpp"
#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/plan_tree.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/task/validate.hpp"
#include "rtamp/batch/resume.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/file_set.hpp"
#include "rtamp/util/output_file.hpp"
#include "rtamp/util/text_file.hpp"
#include "rtamp/world/scenario_io.hpp"

namespace {

using namespace rtamp;
using Clock = std::chrono::steady_clock;

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free);
extern "C" void on_batch_signal(int sig) { g_signal.store(sig); }

struct BatchArgs {
  std::string scenario, world = "mujoco", perception = "truth";
  std::vector<std::string> perception_cameras;
  std::vector<std::string> merge;
  int trials = 30;
  std::vector<std::string> changes;
  std::vector<std::string> algos;
  std::vector<std::string> bts;
  std::uint64_t seed = 1;
  std::string shard;
  int jobs = 2;
  std::string output;
  bool json = false;
  bool markdown = false;
  std::string format = "text";
  std::string group_by = "scenario,change,algorithm,bt";
  double max_time = 900;
  std::string cost = "euclid";
  std::string log_dir;
  bool mcap = false;
  double mcap_image_period = 1;
  rtamp::episode::McapProfile mcap_profile = rtamp::episode::McapProfile::Json;
  bool scripted = false;
  bool no_randomize = false;
  bool quiet = false;
  bool resume = false;
  std::vector<world::TaskChange> new_tasks;
  CLI::Option* change_opt = nullptr;
  CLI::Option* algo_opt = nullptr;
  CLI::Option* bt_opt = nullptr;
  CLI::Option* output_opt = nullptr;
};

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", s);
  return buf;
}

void print_summary(const BatchArgs& a, const std::vector<batch::EpisodeRecord>& records) {
  const batch::Summary s = batch::summarize(records, batch::parse_grouping(a.group_by));
  std::string format = a.json ? "json" : a.markdown ? "markdown" : a.format;
  if (format == "json") {
    std::cout << batch::to_json(s, 2) << "\n";
  } else if (format == "markdown") {
    std::cout << batch::format_markdown(s);
  } else if (format == "tsv") {
    std::cout << batch::format_tsv(s);
  } else {
    std::cout << batch::format_text(s);
  }
  std::cout.flush();
}

// Replaces the regular file `path` atomically with the records in canonical
// order (a FIFO or a device is written directly: it is never replaced).
void write_sorted(const std::string& path, std::vector<batch::EpisodeRecord> records) {
  batch::sort_canonical(records);
  struct stat st{};
  if (::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
    batch::write_csv_file(path, records);
    return;
  }
  const std::string tmp = path + ".tmp";
  batch::write_csv_file(tmp, records);
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw OutputError("--output: cannot replace '" + path + "': " + ec.message());
}

// The log directory, made (or checked) before anything else is written: a
// file written and removed in it proves it takes files.
void prepare_log_dir(const std::string& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw OutputError("--log-dir: cannot write into '" + dir + "': " + ec.message());
  std::string probe = (std::filesystem::path(dir) / ".rtamp-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0)
    throw OutputError("--log-dir: cannot write into '" + dir + "': " + std::error_code(errno, std::generic_category()).message());
  ::close(fd);
  ::unlink(probe.c_str());
}

template <typename E>
std::vector<E> parse_all(const std::vector<std::string>& names, E (*parse)(std::string_view)) {
  std::vector<E> out;
  for (const auto& n : names) out.push_back(parse(n));
  return out;
}

int run_merge(const BatchArgs& a) {
  if (!a.scenario.empty())
    throw Error("give either a scenario to run or --merge CSV files, not both (scenario '" + a.scenario + "')");
  if (!a.output.empty()) {  // the output is none of the files merged (by device and inode)
    FileSet files;
    for (const std::string& m : a.merge) files.input("--merge", m);
    files.output("--output", a.output);
  }
  auto records = batch::merge_files(a.merge);
  // Explicit --algo / --bt / --change select rows.
  auto keep = [&](const batch::EpisodeRecord& r) {
    auto has = [](const std::vector<std::string>& v, const std::string& x) {
      return std::find(v.begin(), v.end(), x) != v.end();
    };
    if (a.algo_opt->count() && !has(a.algos, r.algorithm)) return false;
    if (a.bt_opt->count() && !has(a.bts, r.bt)) return false;
    if (a.change_opt->count() && !has(a.changes, r.change)) return false;
    return true;
  };
  std::erase_if(records, [&](const auto& r) { return !keep(r); });
  if (!a.output.empty()) {
    rtamp::cli::check_output_file("--output", a.output);
    write_sorted(a.output, records);
    std::cerr << "rtamp batch: merged " << a.merge.size() << " file(s), " << records.size() << " episodes into "
              << a.output << "\n";
  }
  print_summary(a, records);
  return 0;
}

int run_batch(const BatchArgs& a) {
  if (a.scenario.empty()) throw Error("rtamp batch needs a scenario (or --merge CSV files)");
  const world::Scenario scenario = world::load_scenario(a.scenario);
  task::validate_task(scenario);  // a bad task is refused once, not run as failed trials
  if (!a.output.empty()) {
    FileSet files;
    if (path_exists(a.scenario)) files.input("SCENARIO", a.scenario);
    files.output("--output", a.output);
    rtamp::cli::check_output_file("--output", a.output);
  }
  if (!a.log_dir.empty()) rtamp::cli::check_output_dir("--log-dir", a.log_dir);
  if (a.mcap && a.log_dir.empty()) throw Error("--mcap: writes one MCAP file per episode into --log-dir; give --log-dir");
  if (a.resume && a.output.empty()) throw Error("--resume: resumes the --output CSV of an interrupted batch; give -o");
  batch::Grid grid;
  grid.algorithms = parse_all(a.algos, plan::parse_algorithm);
  grid.changes = parse_all(a.changes, batch::parse_change_kind);
  grid.bt_variants = parse_all(a.bts, batch::parse_bt_variant);
  grid.trials = a.trials;
  grid.base_seed = a.seed;
  auto trials = batch::make_trials(grid);
  const std::size_t grid_size = trials.size();
  if (!a.shard.empty()) trials = batch::select_shard(trials, batch::parse_shard(a.shard));

  batch::BatchOptions opt;
  opt.jobs = a.jobs;
  opt.log_dir = a.log_dir;
  opt.mcap = a.mcap;
  opt.episode = batch::batch_episode_defaults(a.world);
  opt.episode.world_settings.perception = a.perception;
  opt.episode.world_settings.perception_cameras = a.perception_cameras;
  episode::perception_cameras(scenario, opt.episode.world_settings);  // refused once, not run as failed trials
  opt.episode.outputs.mcap_image_period = a.mcap_image_period;
  opt.episode.outputs.mcap_profile = a.mcap_profile;
  opt.episode.loop.max_time = a.max_time;
  opt.episode.loop.planner.cost = a.cost;
  opt.episode.randomize_initial = !a.no_randomize;
  opt.episode.scripted_operator = a.scripted;
  opt.episode.loop.task_changes = a.new_tasks;
  {  // the new tasks as every episode will have them: refused once, not run as failed trials
    std::vector<world::TaskChange> all = a.new_tasks;
    if (a.scripted) all.insert(all.begin(), scenario.task_changes.begin(), scenario.task_changes.end());
    (void)exec::check_task_schedule(scenario, all, a.max_time);
  }

  // Rows are appended as episodes finish (so a killed batch keeps what it
  // did, and --resume goes on from there), then the file is rewritten in
  // canonical order at the end. The CSV is locked while the batch writes it.
  // A FIFO or a device gets the sorted rows once, at the end.
  OutputFile csv;
  bool appending = false;
  std::vector<batch::EpisodeRecord> kept;  // rows of an earlier run (--resume)
  std::size_t keep_bytes = 0;              // of the file: its whole rows (--resume), else nothing
  bool has_header = false;
  if (!a.output.empty()) {
    // Locked, and read while it is locked, before anything is changed or runs.
    csv = OutputFile(a.output, "--output", OutputFile::Lock::Exclusive, OutputFile::Open::Keep);
    appending = csv.regular();
    if (a.resume) {
      if (!csv.regular()) throw Error("--resume: '" + a.output + "' is not a regular file (nothing to resume from)");
      const batch::Resumed r =
          batch::resume(read_text_file(a.output, "the CSV file", batch::kMaxCsvBytes), a.output, scenario.name, trials);
      kept = r.kept;
      trials = r.missing;
      keep_bytes = r.whole_bytes;  // a torn last line dropped
      has_header = r.has_header;
    }
  }
  const std::size_t planned = kept.size() + trials.size();
  // The log directory before the CSV changes: one that takes no file leaves the CSV as it was.
  if (!a.log_dir.empty()) {
    try {
      prepare_log_dir(a.log_dir);
    } catch (...) {
      if (csv.created()) csv.discard();  // no CSV left behind by a refused batch
      throw;
    }
  }
  if (appending) {
    csv.resize(keep_bytes);
    if (!has_header) {
      std::ostringstream header;
      batch::write_header(header);
      csv.write(header.str());
    }
  }
  if (a.resume && !a.quiet)
    std::cerr << "rtamp batch: resuming " << a.output << ": " << kept.size() << " episode(s) kept, " << trials.size()
              << " to run\n";
  opt.episode.loop.interrupt = &g_signal;
  std::signal(SIGINT, on_batch_signal);
  std::signal(SIGTERM, on_batch_signal);

  const bool tty = !a.quiet && ::isatty(STDERR_FILENO);
  std::cerr << "rtamp batch: " << scenario.name << ", " << trials.size() << " episode(s)";
  if (!a.shard.empty()) std::cerr << " (shard " << a.shard << " of " << grid_size << ")";
  std::cerr << " on " << a.jobs << " worker(s)\n";

  const auto t0 = Clock::now();
  std::mutex mutex;  // guards progress and stderr
  batch::Progress progress;
  progress.total = trials.size();
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  auto redraw = [&] {  // caller holds the mutex
    progress.elapsed_s = elapsed();
    std::cerr << "\r" << batch::progress_bar(progress) << "\x1b[K" << std::flush;
  };
  bool finished = false;
  std::condition_variable cv;
  std::thread ticker;
  if (tty) {
    ticker = std::thread([&] {
      std::unique_lock lock(mutex);
      while (!finished) {
        redraw();
        cv.wait_for(lock, std::chrono::seconds(1));
      }
    });
  }

  std::vector<batch::EpisodeRecord> records = kept;
  try {
    (void)batch::run_batch(scenario, trials, opt, [&](const batch::Trial& t, const batch::EpisodeRecord& r) {
      records.push_back(r);
      if (appending) {
        std::ostringstream row;
        batch::write_record(row, r);
        csv.write(row.str());
      }
      std::lock_guard lock(mutex);
      ++progress.done;
      if (!r.success) ++progress.failures;
      if (tty) {
        if (!r.success) {
          std::cerr << "\r\x1b[K" << "failed: " << batch::describe_key(r) << " (seed " << t.seed << "): " << r.reason
                    << "\n";
        }
        redraw();
      } else if (!a.quiet) {
        progress.elapsed_s = elapsed();
        const double eta = batch::eta_seconds(progress);
        std::cerr << "[" << progress.done << "/" << progress.total << "] " << r.change << " " << r.algorithm << " "
                  << r.bt << " trial " << r.trial << ": " << (r.success ? "ok" : "FAILED") << " (" << r.reason
                  << "), completion " << seconds_text(r.completion_s) << " s, " << r.replans << " replan(s), "
                  << r.tree_changes << " tree change(s), " << seconds_text(r.wall_s) << " s wall; elapsed "
                  << batch::format_duration(progress.elapsed_s) << ", ETA "
                  << (eta < 0 ? std::string("?") : batch::format_duration(eta)) << ", failures " << progress.failures
                  << "\n";
      }
    });
  } catch (...) {
    {
      std::lock_guard lock(mutex);
      finished = true;
    }
    cv.notify_all();
    if (ticker.joinable()) ticker.join();
    std::signal(SIGINT, SIG_DFL);
    std::signal(SIGTERM, SIG_DFL);
    throw;
  }
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  const int sig = g_signal.load();
  {
    std::lock_guard lock(mutex);
    finished = true;
    if (tty) {
      redraw();
      std::cerr << "\n";
    }
  }
  cv.notify_all();
  if (ticker.joinable()) ticker.join();

  if (csv.is_open()) {
    if (appending) {
      csv.close();  // checked: every row is there
      write_sorted(a.output, records);
    } else {
      batch::sort_canonical(records);
      std::ostringstream text;
      batch::write_csv(text, records);
      csv.write(text.str());
      csv.close();
    }
  }
  std::cerr << "rtamp batch: " << records.size() << " episode(s) in " << batch::format_duration(elapsed())
            << ", " << progress.failures << " failed";
  if (sig != 0)
    std::cerr << "; interrupted by " << (sig == SIGTERM ? "SIGTERM" : "SIGINT") << " (" << records.size() << " of "
              << planned << " ran; --resume runs the rest)";
  if (!a.output.empty()) std::cerr << "; wrote " << a.output;
  std::cerr << "\n";
  print_summary(a, records);
  if (sig != 0) return sig == SIGTERM ? 143 : 130;
  const bool failures = std::any_of(records.begin(), records.end(), [](const auto& r) { return !r.success; });
  return failures ? 1 : 0;
}

rtamp::cli::Registrar reg{
    "batch",
    "Run seeded episodes (algorithms x changes x BT variants x trials) and summarize them like the paper's Table I",
    [](CLI::App& sub) -> rtamp::cli::Action {
      auto a = std::make_shared<BatchArgs>();
      a->changes = {"relocate", "remove", "add"};
      a->algos = {"astar-exp", "astar", "dijkstra"};
      a->bts = {"online-action"};
      rtamp::cli::add_scenario(sub, a->scenario);
      sub.add_option("--merge", a->merge, "Join these CSV files (slices of sharded runs) instead of running")
          ->expected(1, -1);
      rtamp::cli::add_integer(sub, "--trials,-n", a->trials, 1, 1000000, "Trials per cell (each with its own seed)");
      std::vector<rtamp::cli::Choice> changes = rtamp::cli::choices_of(rtamp::world::random_change_kinds());
      changes.push_back({"none", "no change"});
      a->change_opt = rtamp::cli::add_choices(sub, "--change", a->changes, changes,
                                              "Random change per episode (repeatable; default: relocate remove add):");
      a->algo_opt = rtamp::cli::add_choices(sub, "--algo", a->algos, rtamp::cli::algorithm_choices(),
                                            "Search algorithm (repeatable; default: all):");
      a->bt_opt = rtamp::cli::add_choices(sub, "--bt", a->bts, rtamp::cli::choices_of(rtamp::exec::tree_variants()),
                                          "BT variant (repeatable; default: online-action):");
      rtamp::cli::add_seed(sub, "--seed", a->seed, "Base seed; trial k's seed is derived from (k, base seed)");
      sub.add_option("--shard", a->shard, "Run only the K-th of N interleaved slices of the trial list (K/N, 1-based)");
      rtamp::cli::add_integer(sub, "--jobs,-j", a->jobs, 1, 256, "Episodes run in parallel (worker threads)");
      a->output_opt = sub.add_option("--output,-o", a->output,
                                     "Per-episode CSV (running: default results.csv; merging: none unless given)");
      sub.add_flag("--json", a->json, "Print the summary as JSON (same as --format json)");
      sub.add_flag("--markdown", a->markdown, "Print the summary as a Markdown table (same as --format markdown)");
      sub.add_option("--format", a->format, "Summary format: text, markdown, json, tsv")
          ->check(CLI::IsMember({"text", "markdown", "json", "tsv"}))
          ->capture_default_str();
      sub.add_option("--group-by", a->group_by,
                     "Summary cells: comma-separated subset of scenario,change,algorithm,bt (others pooled)")
          ->capture_default_str();
      rtamp::cli::add_real(sub, "--max-time", a->max_time, {0, 1e7, true},
                           "Seconds of world time before an episode gives up");
      rtamp::cli::add_choice(sub, "--cost", a->cost, rtamp::cli::cost_model_choices(), "Planner motion-cost model:");
      rtamp::cli::add_new_task(sub, a->new_tasks);
      sub.add_option("--log-dir", a->log_dir, "Write each episode's JSON Lines log into this directory");
      sub.add_flag("--mcap", a->mcap,
                   "Also write each episode as MCAP into --log-dir, beside its log (the same name, .mcap; zstd; "
                   "docs/formats.md)");
      rtamp::cli::add_mcap_image_period(sub, a->mcap_image_period);
      rtamp::cli::add_choice_with(
          sub, "--mcap-profile", rtamp::cli::mcap_profile_choices(), "json",
          [a](const std::string& s) { a->mcap_profile = rtamp::episode::parse_mcap_profile(s); },
          "Profile of the --mcap files (docs/formats.md):");
      rtamp::cli::add_choice(sub, "--world", a->world, rtamp::cli::world_choices(), "World:");
      rtamp::cli::add_choice(sub, "--perception", a->perception, rtamp::cli::perception_choices(),
                             "How the robot perceives:");
      rtamp::cli::add_perception_cameras(sub, a->perception_cameras);
      sub.add_flag("--scripted", a->scripted, "Also apply the scenario's own operator script in every episode");
      sub.add_flag("--no-randomize", a->no_randomize, "Keep the scenario's initial object positions");
      sub.add_flag("--quiet,-q", a->quiet, "No progress on standard error");
      sub.add_flag("--resume", a->resume,
                   "Keep the whole rows of the --output CSV an interrupted batch left and run only the missing trials");
      return [a]() -> int {
        batch::parse_grouping(a->group_by);  // reject a bad --group-by before running anything
        if (!a->merge.empty()) return run_merge(*a);
        if (!a->output_opt->count()) a->output = "results.csv";
        return run_batch(*a);
      };
    }};

}  // namespace
