// The CDR encoder (rtamp/ros2/cdr_writer.hpp) and the messages generated from the
// .msg files, against bytes computed by hand from the rules of XCDR1 (little-endian,
// encapsulation 00 01 00 00, alignment counted after it), and the generated ros2msg
// schema text against the .msg files themselves.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "rtamp/ros2/cdr_writer.hpp"
#include "rtamp/ros2/messages.hpp"
#include "rtamp_source_dir.hpp"

namespace rtamp::ros2 {
namespace {

std::string hex(const std::string& bytes) {
  static const char* digits = "0123456789abcdef";
  std::string o;
  for (unsigned char c : bytes) {
    if (!o.empty()) o += ' ';
    o += digits[c >> 4];
    o += digits[c & 15];
  }
  return o;
}

std::string msg_file(const std::string& rel) {
  std::ifstream in(std::string(RTAMP_SOURCE_DIR) + "/src/rtamp/ros2/msg/" + rel, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(CdrWriter, StartsWithTheLittleEndianEncapsulation) { EXPECT_EQ(hex(CdrWriter().bytes()), "00 01 00 00"); }

TEST(CdrWriter, AlignsPrimitivesToTheirSizeAfterTheHeader) {
  CdrWriter w;
  w.put(std::uint8_t{0xaa});          // 0
  w.put(std::uint16_t{0x0102});       // pad 1, at 2
  w.put(std::uint8_t{0xbb});          // 4
  w.put(std::uint32_t{0x01020304});   // pad 3, at 8
  w.put(true);                        // 12
  w.put(1.0);                         // pad 3, at 16 (8-byte alignment: XCDR1)
  w.put(std::int8_t{-1});             // 24
  w.put(1.5f);                        // pad 3, at 28
  EXPECT_EQ(hex(w.bytes()),
            "00 01 00 00 "
            "aa 00 02 01 bb 00 00 00 04 03 02 01 01 00 00 00 "
            "00 00 00 00 00 00 f0 3f ff 00 00 00 00 00 c0 3f");
}

TEST(CdrWriter, StringsCountTheirNulAndSequencesTheirElements) {
  CdrWriter w;
  w.put(std::uint8_t{7});
  w.put(std::string("ab"));  // pad 3, length 3, a b NUL
  w.count(2);                // pad 1, at 12
  w.put(std::string(""));    // length 1, NUL
  EXPECT_EQ(hex(w.bytes()), "00 01 00 00 07 00 00 00 03 00 00 00 61 62 00 00 02 00 00 00 01 00 00 00 00");
}

TEST(GeneratedMessages, StringIsItsBytes) {
  std_msgs::String s;
  s.data = "hi";
  EXPECT_EQ(hex(encode(s)), "00 01 00 00 03 00 00 00 68 69 00");
}

TEST(GeneratedMessages, JointStateByHand) {
  sensor_msgs::JointState j;
  j.header.stamp.sec = 1;
  j.header.stamp.nanosec = 2;
  j.name = {"a"};
  j.position = {0.5};
  EXPECT_EQ(hex(encode(j)),
            "00 01 00 00 "
            "01 00 00 00 02 00 00 00 "  // stamp
            "01 00 00 00 00 "           // frame_id "" (13 bytes so far)
            "00 00 00 01 00 00 00 "     // pad to 16, name: 1 element
            "02 00 00 00 61 00 "        // "a" (26)
            "00 00 01 00 00 00 "        // pad to 28, position: 1 element (32)
            "00 00 00 00 00 00 e0 3f "  // 0.5
            "00 00 00 00 00 00 00 00");  // velocity, effort: empty
}

TEST(GeneratedMessages, NestedMessagesAlignInTheWholeStream) {
  // TransformStamped: header (stamp, frame_id "w"), child "c", then 7 doubles aligned to 8.
  geometry_msgs::TransformStamped t;
  t.header.frame_id = "w";
  t.child_frame_id = "c";
  t.transform.translation.x = 2;
  const std::string b = encode(t);
  // 8 stamp + 4+2 "w" + pad 2 + 4+2 "c" = 22, pad to 24, 7 doubles: 80 bytes, with the header 84.
  ASSERT_EQ(b.size(), 84u);
  EXPECT_EQ(hex(b.substr(4 + 24, 8)), "00 00 00 00 00 00 00 40");  // translation.x
  EXPECT_EQ(hex(b.substr(4 + 24 + 48, 8)), "00 00 00 00 00 00 f0 3f");  // rotation.w: the .msg's default 1
}

TEST(GeneratedMessages, ConstantsAndDefaultsAreTheMsgFiles) {
  EXPECT_EQ(visualization_msgs::Marker::CUBE, 1);
  EXPECT_EQ(visualization_msgs::Marker::TEXT_VIEW_FACING, 9);
  EXPECT_EQ(visualization_msgs::Marker::DELETE, 2);
  EXPECT_EQ(rcl_interfaces::Log::WARN, 30);
  EXPECT_EQ(geometry_msgs::Quaternion{}.w, 1.0);
  EXPECT_EQ(geometry_msgs::Quaternion{}.x, 0.0);
  EXPECT_EQ(sensor_msgs::JointState::ros2_name, "sensor_msgs/msg/JointState");
}

TEST(GeneratedMessages, SchemaIsTheMsgFileThenEachDependencyOnce) {
  const std::string sep = std::string(80, '=') + "\n";
  const std::string expected = msg_file("sensor_msgs/JointState.msg") + sep + "MSG: std_msgs/Header\n" +
                               msg_file("std_msgs/Header.msg") + sep + "MSG: builtin_interfaces/Time\n" +
                               msg_file("builtin_interfaces/Time.msg");
  EXPECT_EQ(std::string(sensor_msgs::JointState::ros2msg()), expected);
  // TFMessage -> TransformStamped -> Header -> Time, Transform -> Vector3, Quaternion: depth first, once each.
  const std::string tf(tf2_msgs::TFMessage::ros2msg());
  std::vector<std::string> deps;
  for (auto at = tf.find("\nMSG: "); at != std::string::npos; at = tf.find("\nMSG: ", at + 1))
    deps.push_back(tf.substr(at + 6, tf.find('\n', at + 6) - at - 6));
  EXPECT_EQ(deps, (std::vector<std::string>{"geometry_msgs/TransformStamped", "std_msgs/Header", "builtin_interfaces/Time",
                                            "geometry_msgs/Transform", "geometry_msgs/Vector3", "geometry_msgs/Quaternion"}));
}

}  // namespace
}  // namespace rtamp::ros2
