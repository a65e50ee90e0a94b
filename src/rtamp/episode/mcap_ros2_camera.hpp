// Camera perception's frames in an episode's ros2-profile MCAP file (mcap_ros2.hpp),
// as image_transport and RViz name them: per camera NAME,
//   /camera/NAME/image/compressed  sensor_msgs/CompressedImage  the RGB frame as PNG (format "png")
//   /camera/NAME/camera_info       sensor_msgs/CameraInfo       the pinhole intrinsics (K, P; no distortion)
//   /tf                            tf2_msgs/TFMessage           world -> camera/NAME, the optical frame
//                                                              (z forward, x right, y down; a wrist camera moves)
// all stamped with the frame's world time, header frame_id camera/NAME — so a viewer
// places the image in 3-D. Written at the same times as the JSON profile's images
// (`--mcap-image-period`: the first frame, then each frame `period` s or more after
// the last one written; 0: every frame). An observer of the frames, not perception.
#pragma once

#include <cstdint>
#include <string>

#include "rtamp/episode/mcap_ros2.hpp"
#include "rtamp/sim/camera_perception.hpp"

namespace rtamp::episode {

class McapRos2Camera {
 public:
  // The channels of camera `camera`, added now; `mcap` must outlive this; `period` >= 0.
  McapRos2Camera(McapRos2& mcap, const std::string& camera, double period);
  // A frame of that camera at world time `t`.
  void frame(double t, const sim::CameraPerception& frame);
  std::uint64_t images() const { return images_; }

 private:
  McapRos2& mcap_;
  std::string frame_id_;
  double period_;
  std::uint16_t image_ = 0, info_ = 0;
  double next_ = -1;
  std::uint64_t images_ = 0;
};

}  // namespace rtamp::episode
