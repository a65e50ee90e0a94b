#include "rtamp/batch/runner.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

#include "rtamp/util/error.hpp"
#include "rtamp/util/output_file.hpp"

namespace rtamp::batch {

episode::EpisodeOptions batch_episode_defaults(const std::string& world) {
  episode::EpisodeOptions e;
  e.world = world;
  e.randomize_initial = true;
  e.scripted_operator = false;
  e.loop.planning = episode::find_world(world).planning;
  return e;
}

episode::EpisodeOptions episode_options(const Trial& t, const BatchOptions& o) {
  episode::EpisodeOptions e = o.episode;
  e.loop.planner.algorithm = t.algorithm;
  // The paper's three BT variants: online reconfiguration with action or
  // state conditions, and offline reconstruction with action conditions.
  switch (t.bt) {
    case BtVariant::OnlineAction:
      e.loop.conditions = exec::ConditionMode::Action;
      e.loop.reconfiguration = exec::Reconfiguration::Online;
      break;
    case BtVariant::OnlineState:
      e.loop.conditions = exec::ConditionMode::State;
      e.loop.reconfiguration = exec::Reconfiguration::Online;
      break;
    case BtVariant::Offline:
      e.loop.conditions = exec::ConditionMode::Action;
      e.loop.reconfiguration = exec::Reconfiguration::Offline;
      break;
  }
  world::RandomChange change = o.episode.person.change.value_or(world::RandomChange{});
  switch (t.change) {
    case ChangeKind::Relocate: change.kind = world::Intervention::Kind::Relocate; break;
    case ChangeKind::Add: change.kind = world::Intervention::Kind::Add; break;
    case ChangeKind::Remove: change.kind = world::Intervention::Kind::Remove; break;
    case ChangeKind::None: break;
  }
  if (t.change == ChangeKind::None)
    e.person.change.reset();
  else
    e.person.change = change;
  e.seed = t.seed;
  e.outputs.log = o.log_dir.empty() ? std::string() : (std::filesystem::path(o.log_dir) / log_file_name(t)).string();
  e.outputs.log_option = e.outputs.mcap_option = "--log-dir";
  if (o.mcap && !e.outputs.log.empty())
    e.outputs.mcap = std::filesystem::path(e.outputs.log).replace_extension(".mcap").string();
  return e;
}

std::string log_file_name(const Trial& t) {
  return std::string(to_string(t.change)) + "-" + to_string(t.algorithm) + "-" + to_string(t.bt) + "-" +
         std::to_string(t.index) + ".jsonl";
}

EpisodeRecord make_record(const std::string& scenario, const Trial& t, const exec::EpisodeMetrics& m) {
  EpisodeRecord r;
  r.scenario = scenario;
  r.algorithm = to_string(t.algorithm);
  r.bt = to_string(t.bt);
  r.change = to_string(t.change);
  r.trial = t.index;
  r.seed = t.seed;
  r.success = m.success;
  r.reason = m.reason;
  r.first_plan_s = m.first_plan_seconds;
  r.replan_s = m.replan_seconds;
  r.replans = m.replans;
  r.tree_changes = m.tree_changes;
  r.completion_s = m.completion_time.value_or(0);  // summaries average it over successes only
  r.motion_cost = m.motion_cost;
  r.interventions = m.interventions;
  r.wall_s = m.wall_seconds;
  r.rtf = m.real_time_factor;
  return r;
}

std::vector<EpisodeRecord> run_batch(const world::Scenario& scenario, const std::vector<Trial>& trials,
                                     const BatchOptions& options, const EpisodeDone& on_done) {
  if (options.jobs < 1) throw Error("--jobs must be at least 1");
  if (!options.log_dir.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.log_dir, ec);
    if (ec) throw Error("cannot create the log directory '" + options.log_dir + "': " + ec.message());
  }
  std::vector<EpisodeRecord> out(trials.size());
  std::atomic<std::size_t> next{0};
  std::mutex done_mutex;
  std::exception_ptr callback_error;
  const auto* interrupt = options.episode.loop.interrupt;
  auto interrupted = [&] { return interrupt && interrupt->load() != 0; };
  auto worker = [&] {
    for (;;) {
      if (interrupted()) return;
      const std::size_t i = next.fetch_add(1);
      if (i >= trials.size()) return;
      const Trial& t = trials[i];
      EpisodeRecord r;
      try {
        const exec::EpisodeMetrics m = episode::run_episode(scenario, episode_options(t, options));
        if (m.end == exec::EndReason::Interrupted) return;  // not a trial's result: run again on --resume
        r = make_record(scenario.name, t, m);
      } catch (const OutputError&) {
        std::lock_guard lock(done_mutex);
        if (!callback_error) callback_error = std::current_exception();
        next.store(trials.size());
        return;
      } catch (const std::exception& e) {
        exec::EpisodeMetrics m;
        m.reason = std::string("error: ") + e.what();
        r = make_record(scenario.name, t, m);
      }
      std::lock_guard lock(done_mutex);
      out[i] = r;
      if (on_done && !callback_error) {
        try {
          on_done(t, out[i]);
        } catch (...) {
          // Stop handing out work; rethrown below on the calling thread.
          callback_error = std::current_exception();
          next.store(trials.size());
        }
      }
    }
  };
  const int n = std::max(1, std::min<int>(options.jobs, static_cast<int>(std::max<std::size_t>(trials.size(), 1))));
  std::vector<std::thread> pool;
  for (int k = 1; k < n; ++k) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (callback_error) std::rethrow_exception(callback_error);
  return out;
}

}  // namespace rtamp::batch
