// The hub of `rtamp serve` (docs/serve.md): what every page sees, shared between
// the episode's thread and the server's connections — the episode's log records
// so far (hello's `history`), the latest tree, frame, camera image and playback
// state — and the broadcast of every new message to every connected client.
//
// Log records are sent in batches: log_record() adds a record to the pending
// `log` message, which goes out at once for an urgent record, else with the next
// message of any kind (the frames come 30 times a wall second) or at flush().
// The episode marks its tick records (one per loop step: 2,207 of the 2,255
// records of a MuJoCo 3-block-tray episode) not urgent, so they go out ~30 times
// a second in a few messages instead of one message each, and every other record
// goes out as soon as it is written.
//
// Invariants: a client that join()s gets `hello` (built from the state at that
// instant, every record kept, the tree with its latest statuses, `t` the
// latest frame's, `task` and `automaton` the task in force: the latest record of
// the history that put one in force — an `episode` record with its automaton,
// an applied `task` record — else the constructor's), then that frame and the latest camera image (if any),
// before any later message,
// and never a message or record twice or out of order: join, leave and every
// broadcast hold one lock, and join flushes the pending records first.
// Clients only queue what they are sent (Client::send never blocks), so a slow
// page never holds up the episode. Messages are JSON text, built once, shared.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace rtamp::serve {

// What a message may replace in a client's queue: a newer frame an unsent frame, a
// newer camera image an unsent one; other messages replace nothing.
enum class Slot { None, Frame, Camera };

// One connected page. send() queues and returns at once (called under the hub's lock).
class Client {
 public:
  virtual ~Client() = default;
  virtual void send(std::shared_ptr<const std::string> message, Slot slot) = 0;
};

struct PlaybackState {
  double speed = 1;
  bool paused = false;
  double t = 0;
  bool ended = false;
};

class Hub {
 public:
  // `hello_fields`: the members of hello as a JSON object text
  // ({"mode":..,"world":..,"scene":..,"task":..,"automaton":..}); its task and
  // automaton are the first task's, until a record puts another in force.
  explicit Hub(std::string hello_fields);

  void join(const std::shared_ptr<Client>& c);
  void leave(const Client* c);
  // Forgets every client (the server is stopping).
  void clear();
  std::size_t clients() const { return count_.load(); }

  // hello for a new client (also GET /api/hello).
  std::string hello() const;

  // One record of the episode log (one-line JSON object): kept, and added to the
  // pending `log` message, which is sent now if `urgent`.
  void log_record(const std::string& record, bool urgent = true);
  // Sends the pending `log` message, if any.
  void flush();
  // A `tree` message (kept: hello's `tree` is its body).
  void tree(const std::string& message);
  // Node statuses after a tick (tree_message.hpp's status string): kept (hello's
  // tree shows them) and sent as a `status` message.
  void status(double t, const std::string& statuses);
  // A `frame` message at world time `t`: kept (sent to a client after its hello;
  // hello's `t`), and sent to every client if `broadcast`.
  void frame(double t, const std::string& message, bool broadcast = true);
  // A `camera` message (camera_message.hpp; kept: sent to a client after its hello and frame).
  void camera(std::string message);
  // The playback state: kept (hello's speed, paused, t) and broadcast as `state`.
  void state(const PlaybackState& s);
  PlaybackState state() const;
  // Replay seek: replaces the history (and so the task in force), tree (with
  // `statuses`, a status string, if not empty) and frame, and sends every client a new hello.
  void reset(std::vector<std::string> history, std::string tree, std::string statuses, std::string frame,
             const PlaybackState& s);
  // Number of log records kept.
  std::size_t history_size() const;
  // Messages handed to clients (and replies) not yet written to their sockets
  // nor dropped: clients count them (Server::drain waits for none).
  void count_unsent(long delta) { unsent_ += delta; }
  long unsent() const { return unsent_.load(); }

 private:
  std::string hello_locked() const;
  void broadcast_locked(const std::shared_ptr<const std::string>& m, Slot slot);
  void flush_locked();

  mutable std::mutex mu_;
  std::string fields_;             // hello's fixed members (a JSON object)
  std::string first_task_, task_;  // hello's "task":..,"automaton":.. members: the first task's, the one in force
  std::vector<std::string> history_;  // the log records so far
  std::string batch_;  // the pending `log` message, unterminated ("" = none)
  std::string tree_, frame_;  // latest tree message, latest frame message ("" = none)
  std::string statuses_;      // the tree's statuses since its last change ("" = none)
  std::shared_ptr<const std::string> camera_;  // latest camera message (null = none)
  PlaybackState state_;
  std::vector<std::shared_ptr<Client>> clients_;
  std::atomic<std::size_t> count_{0};
  std::atomic<long> unsent_{0};
};

std::string state_message(const PlaybackState& s);

}  // namespace rtamp::serve
