// `rtamp serve --replay LOG` (docs/serve.md "Replay"): a finished episode's
// JSON Lines log (from `rtamp run --log` or `rtamp serve --log`) served to
// pages as if it ran again — its records in time order as `log` messages,
// paced to wall time x speed, with pause, resume, step (to the next record)
// and seek. Frames come from the log's `frame` records (a served episode
// writes them); a log without them has things drawn at their logged
// locations (the latest `perceived` placement, else `run` state; laid out by
// ThingLayout) and the arm parked at home.
//
// The behavior tree is rebuilt from the log's `plan` and `tree` records
// (LoggedTree): a `tree` message where the live episode sent one for a plan.
// Its node statuses are the log's `statuses` records (and the `end` record's
// "statuses"), which `rtamp serve --log` writes, sent as `status` messages; a
// log without them (`rtamp run`) shows every node IDLE. Things added by
// interventions have the class their `intervention` record names.
//
// seek(t) re-sends every page a hello whose history holds the records with
// time <= t and whose tree is the tree at t with the statuses at t (the latest
// statuses logged at or before t and after that tree's change), then the frame at t. The end of the log is the episode's end
// state: the last frame shows the placement of the `end` record.
//
// Invariants: the log is read and checked whole by the constructor before
// anything is served (rtamp::Error "--replay: FILE:LINE: WHY" on a line beyond
// the limits or breaking the record schema: episode/log_check.hpp, the check
// `rtamp log to-mcap` makes too); reading it and
// every lookup by time are linear or better in the log's size (each record
// keeps the index of the latest frame, placement, tree and statuses up to it); a seek
// sticks (playback never resumes from the time before it); the replay never
// changes; interventions are refused (a replay cannot be changed).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "rtamp/serve/hub.hpp"
#include "rtamp/serve/playback.hpp"
#include "rtamp/serve/request_handler.hpp"
#include "rtamp/exec/thing_layout.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

struct ReplayOptions {
  double speed = 1;
  bool paused = false;
};

class Replay final : public RequestHandler {
 public:
  Replay(const world::Scenario& scenario, const std::string& log_path, ReplayOptions options = {});
  ~Replay() override;

  Hub& hub() override { return *hub_; }
  void handle(const Request& request, Reply reply) override;

  void start();
  void stop();
  bool ended() const { return ended_.load(); }
  double duration() const { return duration_; }
  // The frame message at time t (what a page is sent after seeking there).
  std::string frame_at(double t);

 private:
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  struct Record {
    double t = 0;
    std::string text;
    bool frame = false;
    std::optional<world::Placement> placement;  // perceived / run / end: where things were
    bool statuses_only = false;                 // a `statuses` record (not sent as a log record)
    std::string tree;                           // the tree message when this record changed the tree
    std::string statuses;                       // the node statuses it logs (`statuses`, `end`), or ""
    // Indices of the latest frame, placement, tree change and statuses up to this record (kNone: none).
    std::size_t last_frame = kNone, last_placement = kNone, last_tree = kNone, last_statuses = kNone;
  };

  void run();
  void seek_to(double t);
  void publish(double t);
  std::size_t first_after(double t) const;  // index of the first record with time > t

  world::Scenario scenario_;
  std::vector<Record> records_;
  double duration_ = 0;
  world::Vec3 home_{0, 0, 0};
  exec::ThingLayout layout_;
  Playback playback_;
  std::unique_ptr<Hub> hub_;
  std::thread thread_;
  std::atomic<bool> ended_{false};
  std::atomic<double> seek_{-1};
  double t_ = 0;
  std::size_t next_ = 0;
  std::uint64_t seeks_ = 0;  // seeks done (playback thread)
};

}  // namespace rtamp::serve
