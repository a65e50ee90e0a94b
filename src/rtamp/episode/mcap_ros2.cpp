#include "rtamp/episode/mcap_ros2.hpp"

#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include <nlohmann/json.hpp>

#include "rtamp/episode/detail/log_scene.hpp"
#include "rtamp/robot/ur5_kinematics.hpp"
#include "rtamp/robot/ur5_urdf.hpp"
#include "rtamp/ros2/messages.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/version.hpp"

namespace rtamp::episode {

namespace {

using nlohmann::json;
namespace msg = ros2;

// offered_qos_profiles as rosbag2 writes them (rmw enums: history 1 keep-last,
// reliability 1 reliable, durability 1 transient-local / 2 volatile, liveliness 1 automatic).
std::string qos(int depth, bool latched) {
  return "- history: 1\n  depth: " + std::to_string(depth) + "\n  reliability: 1\n  durability: " +
         (latched ? "1" : "2") +
         "\n  deadline:\n    sec: 0\n    nsec: 0\n  lifespan:\n    sec: 0\n    nsec: 0\n  liveliness: 1\n"
         "  liveliness_lease_duration:\n    sec: 0\n    nsec: 0\n  avoid_ros_namespace_conventions: false";
}

std::uint64_t nanos(double t) { return t <= 0 ? 0 : static_cast<std::uint64_t>(std::llround(t * 1e9)); }

msg::builtin_interfaces::Time stamp(std::uint64_t ns) {
  msg::builtin_interfaces::Time s;
  s.sec = static_cast<std::int32_t>(ns / 1000000000ULL);
  s.nanosec = static_cast<std::uint32_t>(ns % 1000000000ULL);
  return s;
}

msg::std_msgs::Header header(std::uint64_t ns, const std::string& frame) {
  msg::std_msgs::Header h;
  h.stamp = stamp(ns);
  h.frame_id = frame;
  return h;
}

msg::geometry_msgs::TransformStamped transform(std::uint64_t ns, const std::string& parent, const std::string& child,
                                               const Eigen::Isometry3d& t) {
  msg::geometry_msgs::TransformStamped m;
  m.header = header(ns, parent);
  m.child_frame_id = child;
  const Eigen::Vector3d p = t.translation();
  const Eigen::Quaterniond r(t.rotation());
  m.transform.translation.x = p.x();
  m.transform.translation.y = p.y();
  m.transform.translation.z = p.z();
  m.transform.rotation.x = r.x();
  m.transform.rotation.y = r.y();
  m.transform.rotation.z = r.z();
  m.transform.rotation.w = r.w();
  return m;
}

Eigen::Isometry3d pose_of(const world::Vec3& p, const std::array<double, 4>& wxyz) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  t.linear() = Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().toRotationMatrix();
  return t;
}

std::string text_of(const json& j, const char* key) {
  auto it = j.find(key);
  if (it == j.end() || it->is_null()) return "";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

template <typename T>
T number_of(const json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_number() ? it->get<T>() : T{};
}

bool bool_of(const json& j, const char* key) {
  auto it = j.find(key);
  return it != j.end() && it->is_boolean() && it->get<bool>();
}

std::vector<std::uint32_t> states_of(const json& j, const char* key) {
  std::vector<std::uint32_t> out;
  auto it = j.find(key);
  if (it != j.end() && it->is_array())
    for (const auto& x : *it)
      if (x.is_number_unsigned()) out.push_back(x.get<std::uint32_t>());
  return out;
}

std::vector<msg::rtamp_msgs::ThingLocation> locations_of(const json& j, const char* key) {
  std::vector<msg::rtamp_msgs::ThingLocation> out;
  auto it = j.find(key);
  if (it != j.end() && it->is_object())
    for (const auto& [thing, where] : it->items()) {
      msg::rtamp_msgs::ThingLocation l;
      l.thing = thing;
      l.location = where.is_string() ? where.get<std::string>() : "none";
      out.push_back(std::move(l));
    }
  return out;
}

// "move(THING, LOCATION)" -> THING, LOCATION (empty when it is not one).
std::pair<std::string, std::string> move_of(const std::string& action) {
  const auto open = action.find('('), comma = action.find(", "), close = action.rfind(')');
  if (open == std::string::npos || comma == std::string::npos || close == std::string::npos || comma < open ||
      close < comma)
    return {};
  return {action.substr(open + 1, comma - open - 1), action.substr(comma + 2, close - comma - 2)};
}

// A colour per block name (stable, the JSON profile's palette), trays brown.
msg::std_msgs::ColorRGBA thing_color(const std::string& name, bool container) {
  msg::std_msgs::ColorRGBA c;
  c.a = 1;
  if (container) {
    c.r = 0.55f, c.g = 0.38f, c.b = 0.22f;
    return c;
  }
  static const float palette[][3] = {{0.85f, 0.2f, 0.2f}, {0.2f, 0.6f, 0.9f}, {0.95f, 0.75f, 0.15f},
                                     {0.3f, 0.75f, 0.35f}, {0.65f, 0.35f, 0.8f}, {0.95f, 0.5f, 0.15f}};
  const auto k = std::hash<std::string>{}(name) % 6;
  c.r = palette[k][0], c.g = palette[k][1], c.b = palette[k][2];
  return c;
}

// A box (CUBE, centre `centre`, size `size`) and its name above it (TEXT_VIEW_FACING,
// `label_z` above the frame's origin), markers `id` and `id` + 1 of namespaces NS and NS_labels.
void labelled_box(msg::visualization_msgs::MarkerArray& out, const msg::std_msgs::Header& h, const std::string& ns,
                  int id, const world::Vec3& centre, const world::Vec3& size, const msg::std_msgs::ColorRGBA& colour,
                  bool frame_locked, double label_z, double text_height, const std::string& name) {
  msg::visualization_msgs::Marker box;
  box.header = h;
  box.ns = ns;
  box.id = id;
  box.type = msg::visualization_msgs::Marker::CUBE;
  box.action = msg::visualization_msgs::Marker::ADD;
  box.pose.position.x = centre[0];
  box.pose.position.y = centre[1];
  box.pose.position.z = centre[2];
  box.scale.x = size[0];
  box.scale.y = size[1];
  box.scale.z = size[2];
  box.color = colour;
  box.frame_locked = frame_locked;
  msg::visualization_msgs::Marker label = box;
  label.ns = ns + "_labels";
  label.id = id + 1;
  label.type = msg::visualization_msgs::Marker::TEXT_VIEW_FACING;
  label.pose.position.z = label_z;
  label.scale.x = label.scale.y = 0;
  label.scale.z = text_height;
  label.color.r = label.color.g = label.color.b = label.color.a = 1;
  label.text = name;
  out.markers.push_back(std::move(box));
  out.markers.push_back(std::move(label));
}

}  // namespace

struct McapRos2::Impl : detail::LogScene {  // the scenario, layout, arm and things' kinds
  McapWriter out;
  bool live = false;         // frame() was called: the scene comes from it
  bool statics = false;      // /robot_description, /tf_static and the regions are written
  bool metadata = false;     // the rtamp Metadata record is written
  bool arm_statics = false;  // the flange and tool frames are on /tf_static (with the first joint angles)
  std::map<std::string, std::array<double, 4>> shown;  // things on /markers: size, container
  std::map<std::string, int> marker_ids;               // a thing's marker id (its label's: id + 1)
  msg::rtamp_msgs::TreeStatus tree;                    // the last tree record's fields and tick status
  std::map<std::string, std::uint16_t> schemas;        // by ROS 2 type name
  std::uint16_t log, rosout, robot_description, tf_static, joints, tf, markers, plan, tree_ch, automaton,
      intervention, task;
  std::string bytes;

  Impl(const std::string& path, McapCompression c, const world::Scenario* s, std::size_t chunk_bytes,
       const std::string& what)
      : out(path, c, chunk_bytes, what, "ros2", std::string("rtamp ") + version()) {
    log = channel<msg::std_msgs::String>("/rtamp/log", 100, false);
    rosout = channel<msg::rcl_interfaces::Log>("/rosout", 1000, false);
    robot_description = channel<msg::std_msgs::String>("/robot_description", 1, true);
    tf_static = channel<msg::tf2_msgs::TFMessage>("/tf_static", 1, true);
    joints = channel<msg::sensor_msgs::JointState>("/joint_states", 10, false);
    tf = channel<msg::tf2_msgs::TFMessage>("/tf", 100, false);
    markers = channel<msg::visualization_msgs::MarkerArray>("/markers", 10, false);
    plan = channel<msg::rtamp_msgs::Plan>("/rtamp/plan", 10, false);
    tree_ch = channel<msg::rtamp_msgs::TreeStatus>("/rtamp/tree", 10, false);
    automaton = channel<msg::rtamp_msgs::AutomatonState>("/rtamp/automaton", 10, false);
    intervention = channel<msg::rtamp_msgs::Intervention>("/rtamp/intervention", 10, false);
    task = channel<msg::rtamp_msgs::Task>("/rtamp/task", 10, false);
    if (s) use(*s);
  }

  template <typename M>
  std::uint16_t channel(const std::string& topic, int depth, bool latched) {
    return add_channel(topic, std::string(M::ros2_name), std::string(M::ros2msg()), depth, latched);
  }
  std::uint16_t add_channel(const std::string& topic, const std::string& type, const std::string& text, int depth,
                            bool latched) {
    auto [it, added] = schemas.try_emplace(type, 0);
    if (added) it->second = out.add_schema(type, "ros2msg", text);
    return out.add_channel(topic, it->second, "cdr", {{"offered_qos_profiles", qos(depth, latched)}});
  }

  template <typename M>
  void put(std::uint16_t ch, std::uint64_t ns, const M& m) {
    bytes = ros2::encode(m);
    out.write(ch, ns, ns, bytes);
  }

  void rosout_line(std::uint64_t ns, std::uint8_t level, const std::string& ev, const std::string& text) {
    msg::rcl_interfaces::Log m;
    m.stamp = stamp(ns);
    m.level = level;
    m.name = "rtamp." + ev;
    m.msg = text;
    m.file = "";
    m.function = "";
    put(rosout, ns, m);
  }

  // The robot's description and the fixed frames, once (at the first record's time).
  void write_statics(std::uint64_t ns) {
    if (statics) return;
    statics = true;
    if (!arm) return;  // no scenario: no robot to describe
    msg::std_msgs::String description;
    description.data = robot::ur5_urdf(arm->config());
    put(robot_description, ns, description);
    msg::tf2_msgs::TFMessage fixed;
    fixed.transforms.push_back(transform(ns, "world", "ur5/base", arm->base()));
    put(tf_static, ns, fixed);
    // The regions: flat boxes with their names, in the world frame.
    msg::visualization_msgs::MarkerArray regions;
    int id = 0;
    msg::std_msgs::ColorRGBA grey;
    grey.r = grey.g = grey.b = 0.6f;
    grey.a = 0.35f;
    for (const auto& r : scenario->regions) {
      labelled_box(regions, header(ns, "world"), "regions", id, {r.center[0], r.center[1], r.center[2] + 0.001},
                   {r.size[0], r.size[1], 0.002}, grey, false, r.center[2] + 0.01, 0.04, r.name);
      id += 2;
    }
    if (!regions.markers.empty()) put(markers, ns, regions);
  }

  void write_metadata(const json& episode) {
    if (metadata) return;
    metadata = true;
    out.add_metadata("rtamp", detail::episode_metadata(episode));
  }

  // One frame: /joint_states and the arm's joints on /tf (when it has joint
  // angles), every present thing on /tf, and /markers when things came, went or changed.
  void scene(std::uint64_t ns, const exec::Frame& f) {
    write_statics(ns);
    msg::tf2_msgs::TFMessage tfs;
    std::optional<Eigen::Isometry3d> tool;
    if (f.q) {
      const auto& q = *f.q;
      msg::sensor_msgs::JointState js;
      js.header = header(ns, "");
      for (std::size_t i = 0; i < robot::kDof; ++i) {
        js.name.emplace_back(robot::ur5_joint_names()[i]);
        js.position.push_back(q[i]);
      }
      put(joints, ns, js);
      if (arm) {
        for (int k = 1; k <= robot::kDof; ++k) {
          const Eigen::Isometry3d t = robot::ur5_joint_origin(arm->config().dh, k) *
                                      Eigen::AngleAxisd(q[static_cast<std::size_t>(k - 1)], Eigen::Vector3d::UnitZ());
          tfs.transforms.push_back(transform(ns, k == 1 ? "ur5/base" : "ur5/link" + std::to_string(k - 1),
                                             "ur5/link" + std::to_string(k), t));
        }
        tool = arm->tool_pose(q);
        if (!arm_statics) {
          // The frames fixed to link6, once the arm's links are on /tf (so that none dangles).
          arm_statics = true;
          msg::tf2_msgs::TFMessage fixed;
          fixed.transforms.push_back(
              transform(ns, "ur5/link6", "ur5/flange", robot::ur5_joint_origin(arm->config().dh, robot::kDof + 1)));
          Eigen::Isometry3d offset = Eigen::Isometry3d::Identity();
          offset.translation() = Eigen::Vector3d(0, 0, arm->tool_offset());
          fixed.transforms.push_back(transform(ns, "ur5/flange", "ur5/tool", offset));
          put(tf_static, ns, fixed);
        }
      }
    }
    msg::visualization_msgs::MarkerArray changes;
    std::set<std::string> now;
    for (const auto& t : f.things) {
      if (t.at == "none") continue;
      now.insert(t.name);
      const std::string frame = "thing/" + t.name;
      const Eigen::Isometry3d pose = pose_of(t.pos, t.quat);
      const bool held = tool && (t.at == "hand" || (!f.held.empty() && t.name == f.held));
      tfs.transforms.push_back(held ? transform(ns, "ur5/tool", frame, tool->inverse() * pose)
                                    : transform(ns, "world", frame, pose));
      const std::array<double, 4> key{t.size[0], t.size[1], t.size[2], t.container ? 1.0 : 0.0};
      auto shown_it = shown.find(t.name);
      if (shown_it != shown.end() && shown_it->second == key) continue;
      shown[t.name] = key;
      auto [id_it, fresh] = marker_ids.try_emplace(t.name, static_cast<int>(2 * marker_ids.size()));
      (void)fresh;
      labelled_box(changes, header(ns, frame), "things", id_it->second, {0, 0, t.size[2] / 2}, t.size,
                   thing_color(t.name, t.container), true, t.size[2] + 0.03, 0.03, t.name);
    }
    for (auto it = shown.begin(); it != shown.end();) {
      if (now.count(it->first)) {
        ++it;
        continue;
      }
      for (int part = 0; part < 2; ++part) {
        msg::visualization_msgs::Marker gone;
        gone.header = header(ns, "thing/" + it->first);
        gone.ns = part == 0 ? "things" : "things_labels";
        gone.id = marker_ids.at(it->first) + part;
        gone.action = msg::visualization_msgs::Marker::DELETE;
        changes.markers.push_back(std::move(gone));
      }
      it = shown.erase(it);
    }
    if (!tfs.transforms.empty()) put(tf, ns, tfs);
    if (!changes.markers.empty()) put(markers, ns, changes);
  }

  bool frames_in_log = false;  // the log has `frame` records: placements are not laid out

  // A placement record ({thing: location}) laid out in its locations (no frames from elsewhere).
  void placement(std::uint64_t ns, double t, const json& p) {
    if (live || frames_in_log) return;
    if (const auto f = laid_out(t, p)) scene(ns, *f);
  }

  void tree_status(std::uint64_t ns) {
    tree.header = header(ns, "");
    put(tree_ch, ns, tree);
  }

  void add(const json& j, std::string_view text) {
    const std::string ev = j.at("ev").get<std::string>();
    const double t = j.at("t").get<double>();
    const std::uint64_t ns = nanos(t);
    {
      msg::std_msgs::String record;
      record.data = std::string(text);
      put(log, ns, record);
    }
    constexpr std::uint8_t info = msg::rcl_interfaces::Log::INFO, warn = msg::rcl_interfaces::Log::WARN,
                           error = msg::rcl_interfaces::Log::ERROR;
    if (ev == "tick") {
      const std::string status = text_of(j, "status"), running = text_of(j, "running");
      if (status != tree.status || running != tree.running) {
        tree.status = status;
        tree.running = running;
        tree_status(ns);
      }
    } else if (ev == "episode") {
      use_builtin(text_of(j, "scenario"));
      write_metadata(j);
      write_statics(ns);
      rosout_line(ns, info, ev,
                  "episode " + text_of(j, "scenario") + ": " + text_of(j, "task") + " (world " + text_of(j, "world") +
                      ", seed " + text_of(j, "seed") + ")");
    } else if (ev == "run") {
      msg::rtamp_msgs::AutomatonState m;
      m.header = header(ns, "");
      m.state = locations_of(j, "state");
      m.automaton_states = states_of(j, "automaton_states");
      put(automaton, ns, m);
    } else if (ev == "perceived") {
      placement(ns, t, j.value("placement", json::object()));
    } else if (ev == "frame") {
      if (live) return;
      frames_in_log = true;
      scene(ns, detail::frame_of_record(t, j));
    } else if (ev == "camera") {
      // The detections and belief are in the /rtamp/log record; nothing else to draw.
    } else if (ev == "plan") {
      msg::rtamp_msgs::Plan m;
      m.header = header(ns, "");
      m.first = bool_of(j, "first");
      m.cost = number_of<double>(j, "cost");
      const json actions = j.value("actions", json::array()), costs = j.value("costs", json::array()),
                 cycle = j.value("in_cycle", json::array());
      for (std::size_t i = 0; i < actions.size(); ++i) {
        msg::rtamp_msgs::Move move;
        move.action = actions[i].is_string() ? actions[i].get<std::string>() : actions[i].dump();
        std::tie(move.thing, move.location) = move_of(move.action);
        move.cost = i < costs.size() && costs[i].is_number() ? costs[i].get<double>() : 0.0;
        move.in_cycle = i < cycle.size() && cycle[i].is_boolean() && cycle[i].get<bool>();
        m.moves.push_back(std::move(move));
      }
      m.automaton_states = states_of(j, "automaton_states");
      m.start = locations_of(j, "start");
      m.hand = text_of(j, "hand");
      m.seconds = number_of<double>(j, "seconds");
      m.expanded = number_of<std::uint64_t>(j, "expanded");
      m.generated = number_of<std::uint64_t>(j, "generated");
      m.cache_hits = number_of<std::uint64_t>(j, "cache_hits");
      m.cache_misses = number_of<std::uint64_t>(j, "cache_misses");
      put(plan, ns, m);
      std::string moves;
      for (const auto& move : m.moves) moves += (moves.empty() ? "" : ", ") + move.action;
      rosout_line(ns, info, ev, std::string(m.first ? "first plan" : "plan") + ", cost " + text_of(j, "cost") + ": " + moves);
    } else if (ev == "tree") {
      tree.applied = bool_of(j, "applied");
      tree.deferred = bool_of(j, "deferred");
      tree.inserted = number_of<std::uint32_t>(j, "inserted");
      tree.removed = number_of<std::uint32_t>(j, "removed");
      tree.updated = number_of<std::uint32_t>(j, "updated");
      tree.changes = number_of<std::uint32_t>(j, "changes");
      tree_status(ns);
      rosout_line(ns, info, ev,
                  std::string(tree.deferred ? "tree change deferred" : "tree changed") + ": inserted " +
                      text_of(j, "inserted") + ", removed " + text_of(j, "removed") + ", updated " + text_of(j, "updated"));
    } else if (ev == "intervention") {
      msg::rtamp_msgs::Intervention m;
      m.header = header(ns, "");
      m.kind = text_of(j, "kind");
      m.subject = text_of(j, "subject");
      m.location = text_of(j, "location");
      m.thing_class = text_of(j, "class");
      m.applied = bool_of(j, "applied");
      m.detail = text_of(j, "detail");
      if (!m.thing_class.empty()) kinds[m.subject] = {m.thing_class, m.kind.find("container") != std::string::npos};
      put(intervention, ns, m);
      rosout_line(ns, m.applied ? info : warn, ev,
                  "intervention: " + m.kind + " " + m.subject + (m.location.empty() ? "" : " -> " + m.location) +
                      (m.applied ? " (applied)" : " (refused)") + (m.detail.empty() ? "" : ": " + m.detail));
    } else if (ev == "task") {
      msg::rtamp_msgs::Task m;
      m.header = header(ns, "");
      m.task = text_of(j, "task");
      m.by = text_of(j, "by");
      m.applied = bool_of(j, "applied");
      m.refused = text_of(j, "refused");
      m.automaton_states = number_of<std::uint32_t>(j, "automaton_states");
      put(task, ns, m);
      rosout_line(ns, m.applied ? info : warn, ev,
                  "new task " + m.task + " (" + m.by + "): " + (m.applied ? "applied" : "refused: " + m.refused));
    } else if (ev == "action") {
      const std::string what = text_of(j, "what"), why = text_of(j, "reason");
      rosout_line(ns, what == "failed" ? warn : info, ev, what + " " + text_of(j, "action") + (why.empty() ? "" : ": " + why));
    } else if (ev == "end") {
      placement(ns, t, j.value("placement", json::object()));
      const bool success = bool_of(j, "success");
      rosout_line(ns, success ? info : text_of(j, "end") == "error" ? error : warn, ev,
                  std::string(success ? "success" : "no success") + " (" + text_of(j, "end") + ")" +
                      (text_of(j, "reason").empty() ? "" : ": " + text_of(j, "reason")));
    } else if (ev == "replan") {
      rosout_line(ns, info, ev, "replan: " + text_of(j, "why"));
    } else if (ev == "handled_by_tree") {
      rosout_line(ns, info, ev, "handled by the tree: " + text_of(j, "by"));
    } else if (ev == "things") {
      rosout_line(ns, info, ev, "things added " + text_of(j, "added") + " removed " + text_of(j, "removed"));
    } else if (ev == "cycle") {
      rosout_line(ns, info, ev, "cycle " + text_of(j, "completed") + " completed");
    } else {
      rosout_line(ns, info, ev, std::string(text));
    }
  }
};

McapRos2::McapRos2(const std::string& path, McapCompression compression, const world::Scenario* scenario,
                   std::size_t chunk_bytes, const std::string& what)
    : impl_(std::make_unique<Impl>(path, compression, scenario, chunk_bytes, what)) {}

McapRos2::~McapRos2() = default;

void McapRos2::discard() noexcept { impl_->out.discard(); }

void McapRos2::add(std::string_view record) {
  impl_->add(detail::parse_record(record), record);
  ++records_;
}

void McapRos2::frame(const exec::Frame& frame) {
  impl_->live = true;
  impl_->scene(nanos(frame.t), frame);
}

std::uint16_t McapRos2::add_channel(const std::string& topic, const std::string& type, const std::string& ros2msg,
                                    int depth, bool latched) {
  return impl_->add_channel(topic, type, ros2msg, depth, latched);
}

void McapRos2::write(std::uint16_t channel, double t, std::string_view cdr) {
  const std::uint64_t ns = nanos(t);
  impl_->out.write(channel, ns, ns, cdr);
}

std::uint16_t McapRos2::tf_channel() const { return impl_->tf; }

void McapRos2::scene_from_frame_records() { impl_->frames_in_log = true; }

void McapRos2::close() { impl_->out.close(); }

}  // namespace rtamp::episode
