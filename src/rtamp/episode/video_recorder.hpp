// Video of a MuJoCo episode: an EpisodeObserver that renders the simulation
// offscreen (sim::Renderer, EGL) after the loop's ticks and writes a frame
// whenever `1/fps` seconds of world time have passed (sim::VideoWriter, an
// ffmpeg pipe). The encoder starts in the constructor, so a bad path or a
// missing ffmpeg fails before the episode does. An encoder that fails during
// the episode (stops reading) throws from on_tick, which ends the episode
// with `error` (its log still gets the end record); close() then throws the
// same rtamp::Error, so the caller reports it after the episode ended.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/exec/episode_observer.hpp"
#include "rtamp/sim/renderer.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::episode {

class VideoRecorder final : public exec::EpisodeObserver {
 public:
  VideoRecorder(const sim::Simulation& sim, const std::string& path, int fps = 30);
  void on_tick(double t, bt::Status, const std::string&) override;
  // Finishes the file (rtamp::Error if the encoder failed, now or earlier).
  void close();
  int frames() const { return writer_->frames(); }

 private:
  std::unique_ptr<sim::Renderer> renderer_;
  std::unique_ptr<sim::VideoWriter> writer_;
  std::vector<std::uint8_t> frame_;
  double period_, next_ = 0;
  std::optional<Error> failed_;  // the encoder's error during the episode
};

}  // namespace rtamp::episode
