#include "rtamp/episode/video_recorder.hpp"

namespace rtamp::episode {

VideoRecorder::VideoRecorder(const sim::Simulation& sim, const std::string& path, int fps)
    : renderer_(std::make_unique<sim::Renderer>(sim)),
      writer_(std::make_unique<sim::VideoWriter>(path, renderer_->width(), renderer_->height(), fps)),
      period_(1.0 / fps) {}

void VideoRecorder::on_tick(double t, bt::Status, const std::string&) {
  if (t < next_ || failed_) return;
  renderer_->render(frame_);
  try {
    while (t >= next_) {  // a tick longer than a frame repeats the frame
      writer_->add(frame_);
      next_ += period_;
    }
  } catch (const Error& e) {
    failed_ = e;
    throw;
  }
}

void VideoRecorder::close() {
  if (failed_) throw *failed_;
  writer_->close();
}

}  // namespace rtamp::episode
