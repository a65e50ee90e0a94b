#include "rtamp/episode/mcap_ros2_camera.hpp"

#include <cmath>

#include "rtamp/ros2/messages.hpp"
#include "rtamp/sim/renderer.hpp"

namespace rtamp::episode {

namespace msg = ros2;

McapRos2Camera::McapRos2Camera(McapRos2& mcap, const std::string& camera, double period)
    : mcap_(mcap), frame_id_("camera/" + camera), period_(period) {
  image_ = mcap_.add_channel<msg::sensor_msgs::CompressedImage>("/camera/" + camera + "/image/compressed");
  info_ = mcap_.add_channel<msg::sensor_msgs::CameraInfo>("/camera/" + camera + "/camera_info");
}

void McapRos2Camera::frame(double t, const sim::CameraPerception& frame) {
  if (next_ >= 0 && t + 1e-9 < next_) return;
  next_ = t + period_;
  const sim::CameraImage& image = frame.image();
  const auto ns = static_cast<std::uint64_t>(std::llround(std::max(t, 0.0) * 1e9));
  msg::std_msgs::Header header;
  header.stamp.sec = static_cast<std::int32_t>(ns / 1000000000ULL);
  header.stamp.nanosec = static_cast<std::uint32_t>(ns % 1000000000ULL);
  header.frame_id = frame_id_;

  // Where the camera is: world -> camera/NAME (the extrinsics map world to camera).
  msg::tf2_msgs::TFMessage tf;
  msg::geometry_msgs::TransformStamped pose;
  pose.header = header;
  pose.header.frame_id = "world";
  pose.child_frame_id = frame_id_;
  const Eigen::Matrix3d r = image.extrinsics.R.transpose();
  const Eigen::Vector3d p = -(r * image.extrinsics.t);
  const Eigen::Quaterniond q(r);
  pose.transform.translation.x = p.x(), pose.transform.translation.y = p.y(), pose.transform.translation.z = p.z();
  pose.transform.rotation.x = q.x(), pose.transform.rotation.y = q.y(), pose.transform.rotation.z = q.z();
  pose.transform.rotation.w = q.w();
  tf.transforms.push_back(std::move(pose));
  mcap_.write(mcap_.tf_channel(), t, ros2::encode(tf));

  msg::sensor_msgs::CameraInfo info;
  info.header = header;
  const sim::Intrinsics& k = image.intrinsics;
  info.width = static_cast<std::uint32_t>(image.width);
  info.height = static_cast<std::uint32_t>(image.height);
  info.distortion_model = "plumb_bob";
  info.d = {0, 0, 0, 0, 0};
  info.k = {k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1};
  info.r = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  info.p = {k.fx, 0, k.cx, 0, 0, k.fy, k.cy, 0, 0, 0, 1, 0};
  mcap_.write(info_, t, ros2::encode(info));

  msg::sensor_msgs::CompressedImage png;
  png.header = header;
  png.format = "png";
  const std::string bytes = sim::encode_png(image.rgb, image.width, image.height);
  png.data.assign(bytes.begin(), bytes.end());
  mcap_.write(image_, t, ros2::encode(png));
  ++images_;
}

}  // namespace rtamp::episode
