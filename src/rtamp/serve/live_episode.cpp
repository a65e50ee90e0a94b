#include "rtamp/serve/live_episode.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include <nlohmann/json.hpp>

#include "rtamp/episode/sim_world.hpp"
#include "rtamp/exec/laid_out_frames.hpp"
#include "rtamp/serve/camera_message.hpp"
#include "rtamp/serve/frame.hpp"
#include "rtamp/serve/paced_world.hpp"
#include "rtamp/serve/scene_message.hpp"
#include "rtamp/serve/tree_message.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::serve {

namespace {
using Clock = std::chrono::steady_clock;
constexpr auto kFrameInterval = std::chrono::microseconds(1000000 / 30);
constexpr auto kCameraInterval = std::chrono::milliseconds(200);  // at most 5 camera images a wall second
bool is_frame_record(const std::string& r) { return r.rfind("{\"ev\":\"frame\"", 0) == 0; }
// Pages get the node statuses as `status` messages, not as these records.
bool is_statuses_record(const std::string& r) { return r.rfind("{\"ev\":\"statuses\"", 0) == 0; }
// Tick records (one a loop step) go to pages in batches (Hub::log_record).
bool is_tick_record(const std::string& r) { return r.rfind("{\"ev\":\"tick\"", 0) == 0; }
}  // namespace

// The loop's events a page sees besides the log: the tree, statuses, perception (for frames), the end.
// With a log file, node statuses also go into it (`statuses` records, the end record's
// "statuses"), so that a replay shows them: after every tick that changed some and
// after every tree change (a reconfigured tree keeps the statuses of the subtrees it kept).
class LiveEpisode::Observer final : public exec::EpisodeObserver {
 public:
  explicit Observer(LiveEpisode& e) : e_(e) {}

  void on_perceived(double, const world::Placement& seen, const world::Placement&) override {
    e_.seen_ = seen;
    e_.check_->note(seen);
  }
  void on_tree_change(double t, const exec::ReconfigurationReport&, const exec::PlanTree& tree, bool) override {
    send_tree(t, tree.tree());
  }
  // Statuses are kept even without a page: one that joins sees the present.
  void on_tick(double t, bt::Status, const std::string&) override {
    const bt::Tree& tree = e_.episode_->loop().tree().tree();
    std::string s = status_string(tree);
    if (s.size() != nodes_) {
      send_tree(t, tree);
    } else if (s != last_) {
      send_status(t, std::move(s));
    }
  }
  // The statuses the tree ends with (a tree running at the end was halted:
  // ReactiveLoop::finish), after the end record (which carries them too).
  void on_end(double t, const exec::EpisodeMetrics&, const world::Placement&) override {
    std::string s = status_string(e_.episode_->loop().tree().tree());
    if (s.size() == nodes_ && s != last_) {
      last_ = s;
      e_.hub_->status(t, s);
    }
    e_.ended_.store(true);
    e_.emit_frame(true);
    e_.publish_state();
  }

 private:
  void send_tree(double t, const bt::Tree& tree) {
    last_ = status_string(tree);
    nodes_ = last_.size();
    e_.hub_->tree(tree_message(t, tree));
    log_statuses(t);
  }
  void send_status(double t, std::string s) {
    e_.hub_->status(t, s);
    last_ = std::move(s);
    log_statuses(t);
  }
  void log_statuses(double t) {
    if (!e_.own_log_) e_.log_->record(t, "{\"ev\":\"statuses\",\"s\":\"" + last_ + "\"}");
  }

  LiveEpisode& e_;
  std::string last_;
  std::size_t nodes_ = 0;
};

LiveEpisode::LiveEpisode(const world::Scenario& scenario, LiveOptions options)
    : options_(std::move(options)), playback_(options_.speed, options_.paused) {
  episode_ = std::make_unique<episode::Episode>(
      scenario, options_.episode, [this](exec::World& inner) -> std::unique_ptr<exec::World> {
        return std::make_unique<PacedWorld>(inner, playback_, [this] { service(); }, [this] { after_slice(); },
                                            [this] { return std::exchange(changed_, false); });
      });
  frames_ = episode_->world().frames();
  if (!frames_) {
    laid_out_ = std::make_unique<exec::LaidOutFrames>(episode_->scenario(), episode_->world());
    frames_ = laid_out_.get();
  }
  if (exec::Intervenable* hands = episode_->world().intervenable()) seen_ = hands->true_placement();
  arm_ = std::make_unique<ArmAngles>(episode_->scenario().robot);
  check_ = std::make_unique<InterventionCheck>(episode_->scenario());
  hub_ = std::make_unique<Hub>(hello_fields(episode_->scenario(), episode_->loop().progress().automaton(), "live",
                                            options_.episode.world));
  log_ = episode_->log();
  if (!log_) {
    own_log_ = std::make_unique<exec::EpisodeLog>();
    log_ = own_log_.get();
    episode_->loop().add_observer(*log_);
  }
  log_->add_sink([this](const std::string& record) {
    if (!is_frame_record(record) && !is_statuses_record(record)) hub_->log_record(record, !is_tick_record(record));
  });
  if (!own_log_)
    log_->add_end_text("statuses", [this] { return status_string(episode_->loop().tree().tree()); });
  if (episode::SimWorld* sw = episode_->sim_world())
    if (sw->session().perception().camera())
      sw->session().perception().add_frame_observer([this](const sim::CameraPerception& f) { camera_frame(f); });
  observer_ = std::make_unique<Observer>(*this);
  episode_->loop().add_observer(*observer_);
  PlaybackState s;
  s.speed = options_.speed;
  s.paused = options_.paused;
  hub_->state(s);
}

LiveEpisode::~LiveEpisode() {
  stop();
  if (thread_.joinable()) thread_.join();
}

void LiveEpisode::start() {
  thread_ = std::thread([this] {
    emit_frame(true);
    try {
      metrics_ = episode_->run();
    } catch (...) {
      failed_ = std::current_exception();
    }
    ended_.store(true);
    // Requests that arrived after the last step.
    std::deque<Pending> left;
    {
      std::lock_guard lock(mu_);
      left.swap(pending_);
    }
    for (auto& p : left) p.reply(reply_message(p.request.id, false, "the episode has ended"));
  });
}

void LiveEpisode::stop() {
  episode_->loop().stop();
  playback_.stop();
}

exec::EpisodeMetrics LiveEpisode::wait() {
  if (thread_.joinable()) thread_.join();
  if (failed_) std::rethrow_exception(std::exchange(failed_, nullptr));
  return metrics_;
}

InterventionStats LiveEpisode::stats() const {
  std::lock_guard lock(mu_);
  return stats_;
}

void LiveEpisode::publish_state() {
  PlaybackState s;
  s.speed = playback_.speed();
  s.paused = playback_.paused();
  s.t = episode_->world().time();
  s.ended = ended_.load();
  hub_->state(s);
}

void LiveEpisode::handle(const Request& r, Reply reply) {
  if (r.type == Request::Type::Invalid) {
    reply(reply_message(r.id, false, r.error));
    return;
  }
  if (r.type == Request::Type::Control) {
    const std::string& a = r.action;
    if (a == "seek") {
      reply(reply_message(r.id, false, "seek is for replays (rtamp serve --replay LOG)"));
      return;
    }
    if (a == "speed" && !(*r.value >= 0 && *r.value <= 1000)) {
      reply(reply_message(r.id, false, "speed must be in [0, 1000] (0: as fast as possible)"));
      return;
    }
    if (a == "pause") playback_.pause();
    if (a == "resume") playback_.resume();
    if (a == "step") {
      if (!playback_.paused()) {
        reply(reply_message(r.id, false, "step needs the episode paused"));
        return;
      }
      playback_.step();
    }
    if (a == "speed") playback_.set_speed(*r.value);
    reply(reply_message(r.id, true));
    PlaybackState s = hub_->state();
    s.speed = playback_.speed();
    s.paused = playback_.paused();
    s.ended = ended_.load();
    hub_->state(s);
    return;
  }
  if (r.type == Request::Type::Task) {
    // set_task is thread-safe (the loop takes it in at its next step) and
    // checks the formula at once: a refusal is answered with the Error's
    // message and detail (the formula with a caret under the column).
    world::TaskChange change;
    change.task = r.task;
    change.task_where = SourceLocation{"task", 1, 1};
    change.by = "page";
    change.where = SourceLocation{"page", 0, 0};
    try {
      episode_->loop().set_task(std::move(change));
    } catch (const Error& e) {
      reply(reply_message(r.id, false, e.message(), "\"detail\":" +
          nlohmann::json(e.detail()).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
      return;
    }
    reply(reply_message(r.id, true));
    playback_.wake();
    return;
  }
  // Intervene: queued for the loop's thread.
  {
    std::lock_guard lock(mu_);
    if (ended_.load()) {
      reply(reply_message(r.id, false, "the episode has ended"));
      return;
    }
    if (pending_.size() >= options_.max_pending) {
      reply(reply_message(r.id, false, "too many interventions waiting (" + std::to_string(pending_.size()) + ")"));
      return;
    }
    pending_.push_back(Pending{r, std::move(reply), Clock::now()});
  }
  playback_.wake();
}

void LiveEpisode::service() {
  std::deque<Pending> todo;
  {
    std::lock_guard lock(mu_);
    todo.swap(pending_);
  }
  if (todo.empty()) return;
  exec::Intervenable* hands = episode_->world().intervenable();
  bool reached = false;  // the world applied or refused one: it has an event for the loop to log
  for (Pending& p : todo) {
    if (!hands) {
      p.reply(reply_message(p.request.id, false,
                            "the " + options_.episode.world + " world takes no interventions from pages "
                            "(it has no intervention capability: exec/intervenable.hpp)"));
      continue;
    }
    world::Intervention iv = p.request.intervention;
    iv.time = episode_->world().time();
    const world::Placement now = hands->true_placement();
    check_->note(now);
    using K = world::Intervention::Kind;
    if ((iv.kind == K::Add || iv.kind == K::AddContainer) && iv.subject.empty())
      iv.subject = check_->fresh_name(iv.kind == K::AddContainer);
    if ((iv.kind == K::Add || iv.kind == K::AddContainer) && iv.cls.empty())
      iv.cls = iv.kind == K::AddContainer ? "tray" : "block";
    std::string error = check_->check(iv, now);
    bool ok = error.empty();
    std::string extra;
    if (ok) {
      const exec::WorldEvent e = hands->apply(iv);
      ok = e.applied;
      reached = true;
      if (!ok) error = std::string("intervention '") + kind_name(iv.kind) + "' refused by the world: " + e.detail;
      extra = "\"subject\":" + nlohmann::json(iv.subject).dump() + ",\"detail\":" +
              nlohmann::json(e.detail).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace) + ",";
    }
    const double ms = std::chrono::duration<double, std::milli>(Clock::now() - p.received).count();
    {
      std::lock_guard lock(mu_);
      stats_.latency_ms.push_back(ms);
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "\"server_ms\":%.3f", ms);
    p.reply(reply_message(p.request.id, ok, error, extra + buf));
  }
  if (reached) {
    // The loop logs the world's event now, at the time it took effect, not
    // after the rest of the slice or the advance (whose frame records would
    // come first, later in time: the log would not replay).
    changed_ = true;
    playback_.end_slice();
    emit_frame(true);
  }
}

void LiveEpisode::after_slice() {
  const double t = episode_->world().time();
  // Frame records are for a replay of the log file; without --log (the
  // episode's own in-memory log, whose sink skips them) none is built.
  if (options_.frame_record_period > 0 && !own_log_ && t >= next_frame_record_) {
    log_->record(t, frame_record(frame()));
    next_frame_record_ = t + options_.frame_record_period;
  }
  emit_frame(false);
}

void LiveEpisode::camera_frame(const sim::CameraPerception& f) {
  // Encoded whether or not a page is connected: a page that joins gets the latest. The
  // page shows one camera: the first that perceives.
  if (f.camera_name() != f.cameras().front().name) return;
  const auto now = Clock::now();
  if (now < next_camera_) return;
  next_camera_ = now + kCameraInterval;
  hub_->camera(camera_message(episode_->world().time(), f));
}

exec::Frame LiveEpisode::frame() {
  exec::Frame f = frames_->frame(seen_);
  arm_->fill(f);
  return f;
}

void LiveEpisode::emit_frame(bool force) {
  // Every slice's frame is kept, so that a page that joins gets the present
  // (hello's `t` and first frame not older than any record it has). Pages are
  // sent at most 30 a wall second, counted from when the next one was due (not
  // from the last one sent): a world whose slices come every 20 ms still gets 30.
  const auto now = Clock::now();
  const bool send = force || now >= next_frame_;
  if (send) next_frame_ = std::max(next_frame_ + kFrameInterval, now - kFrameInterval);
  const Frame f = frame();
  hub_->frame(f.t, frame_message(f), send);
}

}  // namespace rtamp::serve
