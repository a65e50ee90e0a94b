// Camera perception's frames in an episode's MCAP file (docs/formats.md "MCAP"): an
// observer of the frames (sim::Perception::add_frame_observer; Episode registers it for
// `--perception camera` with `--mcap`) that writes, per camera NAME,
//   /camera/NAME/image        foxglove.CompressedImage  the frame's RGB image as PNG,
//                                                       frame_id "camera/NAME"
//   /camera/NAME/annotations  foxglove.ImageAnnotations one box per detection with its
//                                                       label (sim/camera_overlay.hpp)
// one image and its annotations every `period` s of world time (`--mcap-image-period`;
// 0: every frame, inf: none): the first frame, then each frame that comes `period` s
// or more after the last one written. Message times are the frames' world times (ns).
#pragma once

#include <cstdint>
#include <string>

#include "rtamp/episode/episode_mcap.hpp"
#include "rtamp/sim/camera_perception.hpp"

namespace rtamp::episode {

class McapCamera {
 public:
  // The channels of camera `camera`, added now (before any message); `mcap` must
  // outlive this; `period` > 0, or 0 (every frame). Inf (no images) is the caller's
  // to leave out: no McapCamera, no camera channels.
  McapCamera(EpisodeMcap& mcap, const std::string& camera, double period);
  // A frame of that camera at world time `t`.
  void frame(double t, const sim::CameraPerception& frame);
  std::uint64_t images() const { return images_; }

 private:
  EpisodeMcap& mcap_;
  std::string frame_id_;
  double period_;
  std::uint16_t image_ = 0, annotations_ = 0;
  double next_ = -1;  // world time of the next image (< 0: the first frame's)
  std::uint64_t images_ = 0;
  std::string png_, text_;
};

}  // namespace rtamp::episode
