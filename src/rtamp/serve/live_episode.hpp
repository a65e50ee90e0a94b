// A live served episode (`rtamp serve SCENARIO`, docs/serve.md): the reactive
// loop (exec::ReactiveLoop, the paper's Algorithm 1) on any registered world
// (episode/world_registry.hpp), run on its own thread, paced to wall time x speed
// (PacedWorld, Playback), streamed to pages through the Hub:
//  - every record of the episode's JSON Lines log, exactly as the log file
//    holds it (exec::EpisodeLog's sink), as `log` messages;
//  - the behavior tree after each change and node statuses after ticks that
//    changed them (`tree`, `status`);
//  - frames at most 30 per wall second (drawn by the world, exec/frame.hpp, or
//    laid out from what the loop perceived, exec/laid_out_frames.hpp; joint angles
//    solved for the tool point where the world has none, arm_angles.hpp), and one after each
//    applied intervention; every slice's frame and the tree's statuses after every
//    tick are kept in the Hub, so a page that joins gets the present; the log also
//    gets a `frame` record every `frame_record_period` s of world time (replays
//    move things with them);
//  - with camera perception, the camera's latest image with its detections'
//    boxes (`camera`, camera_message.hpp) at most 5 per wall second; a page that
//    joins gets the latest one;
//  - playback state after each control.
// Pages' interventions (request.hpp) are queued and applied on the loop's
// thread between slices of world time, through the world's intervention
// capability (exec/intervenable.hpp; a world without it refuses them) after InterventionCheck: so
// they enter the log as `intervention` records exactly like scripted ones, and
// the loop reacts to them as to any person's; one that reached the world
// (applied or refused by it) ends the world's advance, so its record, at the
// time it took effect, precedes every record of later world time (the log
// stays in time order and replays). Each gets one reply: refused
// (the check's or the world's reason), or applied, with the server-side
// latency from receipt to applied ("server_ms"). A page's `task` request goes
// straight to ReactiveLoop::set_task (thread-safe; taken in at the loop's next
// step) by "page": a refusal is replied with the Error's message and detail.
//
// Invariants: nothing a page sends can throw on the loop's thread or block it
// (replies and broadcasts only queue); the log is complete whatever ends the
// episode (stop(), SIGINT/SIGTERM through options.interrupt, an error).
#pragma once

#include <atomic>
#include <chrono>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/intervenable.hpp"
#include "rtamp/exec/frame.hpp"
#include "rtamp/serve/arm_angles.hpp"
#include "rtamp/serve/hub.hpp"
#include "rtamp/serve/intervention_check.hpp"
#include "rtamp/serve/playback.hpp"
#include "rtamp/serve/request_handler.hpp"

namespace rtamp::sim {
class CameraPerception;
}

namespace rtamp::serve {

struct LiveOptions {
  episode::EpisodeOptions episode;  // the episode (log_path: the --log file, may be empty)
  double speed = 1;                 // world seconds per wall second; 0: as fast as possible
  bool paused = false;              // start paused (the first plan is made)
  double frame_record_period = 0.5; // s of world time between `frame` log records (0: none)
  std::size_t max_pending = 64;     // queued interventions; more are refused
};

// Server-side timing of the pages' interventions (docs/benchmarks.md).
struct InterventionStats {
  std::vector<double> latency_ms;  // receipt -> applied (or refused) in the world, each
};

class LiveEpisode final : public RequestHandler {
 public:
  // Builds the world, loop and log (rtamp::Error before anything runs on bad input).
  LiveEpisode(const world::Scenario& scenario, LiveOptions options);
  ~LiveEpisode() override;

  Hub& hub() override { return *hub_; }
  void handle(const Request& request, Reply reply) override;

  void start();                // the loop's thread
  void stop();                 // ends the episode at its next step (Interrupted)
  // Joins the loop's thread; the end metrics. An output lost while the episode ran
  // (Episode::run's rtamp::OutputError) is rethrown here.
  exec::EpisodeMetrics wait();
  bool ended() const { return ended_.load(); }
  InterventionStats stats() const;

 private:
  struct Pending {
    Request request;
    Reply reply;
    std::chrono::steady_clock::time_point received;
  };
  class Observer;

  void service();           // loop thread: apply queued interventions
  void after_slice();       // loop thread: frames
  void emit_frame(bool force);
  void camera_frame(const sim::CameraPerception& frame);  // loop thread
  exec::Frame frame();
  void publish_state();

  // Declared in the order things may refer to each other: the loop (in
  // episode_) goes first on destruction, its observers and world wrapper after.
  LiveOptions options_;
  Playback playback_;
  std::unique_ptr<Hub> hub_;
  std::unique_ptr<InterventionCheck> check_;
  exec::FrameSource* frames_ = nullptr;          // the world's, or laid_out_
  std::unique_ptr<exec::FrameSource> laid_out_;  // for a world that cannot draw itself
  std::unique_ptr<ArmAngles> arm_;               // joint angles for frames without them
  world::Placement seen_;                         // what the loop perceived last
  std::unique_ptr<exec::EpisodeLog> own_log_;  // when there is no --log file
  std::unique_ptr<Observer> observer_;
  std::unique_ptr<episode::Episode> episode_;
  exec::EpisodeLog* log_ = nullptr;
  std::thread thread_;
  exec::EpisodeMetrics metrics_;
  std::exception_ptr failed_;  // what Episode::run threw, for wait()
  std::atomic<bool> ended_{false};

  mutable std::mutex mu_;
  std::deque<Pending> pending_;
  InterventionStats stats_;

  std::chrono::steady_clock::time_point next_frame_{};  // when the next unforced frame is due
  std::chrono::steady_clock::time_point next_camera_{};  // when the next camera message may go
  bool changed_ = false;  // loop thread: a page's intervention reached the world since the loop last looked
  double next_frame_record_ = 0;
};

}  // namespace rtamp::serve
