// An episode as an MCAP file in the ros2 profile (`--mcap-profile ros2`;
// docs/formats.md "The ros2 profile"): what `ros2 bag play`, RViz and Foxglove
// read as ROS 2 data. Header profile "ros2", library "rtamp VERSION"; every
// message CDR (rtamp/ros2/messages.hpp, generated from the .msg files) with its
// ros2msg schema; every channel with its offered_qos_profiles; a Metadata
// record "rtamp" (version, scenario, world, seed, task). Topics:
//   /rtamp/log          std_msgs/String              every log record, as it is (count = the log's lines)
//   /rosout             rcl_interfaces/Log           one line per event (not ticks, steps, percepts, frames, camera records)
//   /robot_description  std_msgs/String              the UR5's URDF (robot/ur5_urdf.hpp), once, latched
//   /tf_static          tf2_msgs/TFMessage           world -> ur5/base; with the first joint angles
//                                                    ur5/link6 -> ur5/flange -> ur5/tool; latched
//   /joint_states       sensor_msgs/JointState       the arm's six joints, per frame with joint angles
//   /tf                 tf2_msgs/TFMessage           per frame: the arm's joints (URDF links) and every
//                                                    thing as frame thing/NAME (the centre of its base)
//                                                    in world — or in ur5/tool while the arm holds it
//   /markers            visualization_msgs/MarkerArray  regions (once), each thing's box and label in its
//                                                    own frame (frame-locked), sent when things come, go or change size
//   /rtamp/plan, /rtamp/tree, /rtamp/automaton, /rtamp/intervention, /rtamp/task
//                       rtamp_msgs/Plan, TreeStatus, AutomatonState, Intervention, Task
// Frames come live from the world (frame(): McapRos2Frames, every tick) or, in a
// converted log, from its `frame` records, else laid out from its `perceived`
// and `end` placements (exec/thing_layout.hpp) — one source per file, never two.
// Times are the records' world times (ns), header stamps the same.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

#include "rtamp/episode/mcap_writer.hpp"
#include "rtamp/exec/frame.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::episode {

class McapRos2 {
 public:
  // Opens `path` (rtamp::Error if it cannot be written; `what` names it). `scenario` (may be null)
  // gives the regions, the robot's base and the things' classes; without it, the
  // built-in scenario the `episode` record names is used, if it is one.
  McapRos2(const std::string& path, McapCompression compression, const world::Scenario* scenario,
           std::size_t chunk_bytes = 1 << 20, const std::string& what = "--mcap");
  ~McapRos2();
  McapRos2(const McapRos2&) = delete;
  McapRos2& operator=(const McapRos2&) = delete;

  // One record of the log (a JSON object with "ev" and "t"); rtamp::Error if it is not one.
  void add(std::string_view record);
  // The scene as the world draws it, at frame.t. Once called, `frame` records
  // and placements are not drawn (the scene comes from here only).
  void frame(const exec::Frame& frame);
  // A channel of observers that write messages of their own (a camera's images:
  // mcap_ros2_camera.hpp): message type M (a generated one, rtamp/ros2/messages.hpp),
  // its schema written once per type, QoS keep-last `depth`, latched or volatile.
  template <typename M>
  std::uint16_t add_channel(const std::string& topic, int depth = 10, bool latched = false) {
    return add_channel(topic, std::string(M::ros2_name), std::string(M::ros2msg()), depth, latched);
  }
  std::uint16_t add_channel(const std::string& topic, const std::string& type, const std::string& ros2msg, int depth,
                            bool latched);
  // One message of such a channel at world time `t` (s): its CDR bytes (ros2::encode).
  void write(std::uint16_t channel, double t, std::string_view cdr);
  // The /tf channel's id, for observers that place frames of their own (a camera).
  std::uint16_t tf_channel() const;
  // The log has `frame` records (a converted `rtamp serve --log`): the scene comes
  // from them only, not also from the placements before the first one.
  void scene_from_frame_records();
  // Writes the summary and closes the file (the destructor does it quietly).
  void close();
  // Closes quietly and removes the file if it is a regular one.
  void discard() noexcept;

  std::uint64_t records() const { return records_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  std::uint64_t records_ = 0;
};

}  // namespace rtamp::episode
