#include "rtamp/sim/mjcf_builder.hpp"

#include "rtamp/sim/class_colours.hpp"
#include "rtamp/sim/scene_style.hpp"

#include "rtamp/sim/ur5_model.hpp"
#include "rtamp/world/table.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string_view>

namespace rtamp::sim {

namespace {

std::string xml_escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

// Numbers in a fixed, locale-independent form.
struct Num {
  double v;
};
std::ostream& operator<<(std::ostream& os, Num n) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.15g", std::abs(n.v) < 1e-15 ? 0.0 : n.v);
  return os << buf;
}
std::string v3(double x, double y, double z) {
  std::ostringstream o;
  o << Num{x} << ' ' << Num{y} << ' ' << Num{z};
  return o.str();
}
std::string v4(double a, double b, double c, double d) {
  std::ostringstream o;
  o << Num{a} << ' ' << Num{b} << ' ' << Num{c} << ' ' << Num{d};
  return o.str();
}

void check_name(const std::string& n, const SourceLocation& where) {
  if (n.empty()) throw Error("empty name in scenario", where);
  for (char c : n)
    if (static_cast<unsigned char>(c) < 0x20) throw Error("name '" + n + "' holds a control character", where);
}

void tray_geoms(std::ostream& x, const world::Vec3& size, const std::array<double, 3>& rgb, double mass,
                const char* contact, const std::string& gname) {
  const double hx = size[0] / 2, hy = size[1] / 2, h = std::max(size[2], kTrayPlate + 0.005);
  const double rim_h = (h - kTrayPlate) / 2, rt = kTrayRim / 2;  // rims stand on the plate
  const double mplate = mass * 0.5, mrim = mass * 0.125;
  std::string rgba = v4(rgb[0], rgb[1], rgb[2], 1);
  x << "      <geom name=\"" << gname << "/plate\" type=\"box\" size=\"" << v3(hx, hy, kTrayPlate / 2) << "\" pos=\""
    << v3(0, 0, kTrayPlate / 2) << "\" mass=\"" << Num{mplate} << "\" rgba=\"" << rgba << "\"" << contact << "/>\n";
  // Rims along x (at ±y) span the full length; rims along y fit between them.
  for (int s : {-1, 1}) {
    x << "      <geom name=\"" << gname << "/rim_y" << (s < 0 ? "-" : "+") << "\" type=\"box\" size=\""
      << v3(hx, rt, rim_h) << "\" pos=\"" << v3(0, s * (hy - rt), kTrayPlate + rim_h) << "\" mass=\"" << Num{mrim}
      << "\" rgba=\"" << rgba << "\"" << contact << "/>\n";
    x << "      <geom name=\"" << gname << "/rim_x" << (s < 0 ? "-" : "+") << "\" type=\"box\" size=\""
      << v3(rt, hy - 2 * rt, rim_h) << "\" pos=\"" << v3(s * (hx - rt), 0, kTrayPlate + rim_h) << "\" mass=\"" << Num{mrim}
      << "\" rgba=\"" << rgba << "\"" << contact << "/>\n";
  }
}

// The text between <tag> and the last </tag> of the UR5's model file (its one section of
// that name; nested elements of the same name, like <default class=...>, stay inside).
std::string_view model_section(std::string_view model, std::string_view tag) {
  const std::string open = "<" + std::string(tag) + ">", close = "</" + std::string(tag) + ">";
  const auto b = model.find(open), e = model.rfind(close);
  if (b == std::string_view::npos || e == std::string_view::npos || e < b || model.rfind(open) != b)
    throw Error("the UR5 model file has no single <" + std::string(tag) + "> section");
  return model.substr(b + open.size(), e - b - open.size());
}

// The parallel gripper, placed inside the flange body: body "gripper" is the flange frame.
std::string gripper_mjcf(const MjcfOptions& opt) {
  std::ostringstream x;
  const std::string in = "                    ";
  const double to = opt.arm.tool_offset;
  const double tip = to + kFingerTipBelowTcp;
  const double palm_top = 0.0, palm_bot = 0.06;
  x << in << "<body name=\"gripper\" childclass=\"gripper\">\n";
  x << in << "  <site name=\"tcp\" pos=\"" << v3(0, 0, to) << "\" size=\"0.006\" rgba=\"1 0 0 0.5\"/>\n";
  x << in << "  <geom name=\"gripper:palm\" type=\"box\" size=\"" << v3(0.03, opt.finger_max + 0.015, 0.03)
    << "\" pos=\"" << v3(0, 0, (palm_top + palm_bot) / 2) << "\" mass=\"0.6\"/>\n";
  const double fh = (tip - palm_bot) / 2, fz = (tip + palm_bot) / 2;
  for (int sgn : {1, -1}) {
    const char* nm = sgn > 0 ? "left" : "right";
    x << in << "  <body name=\"gripper:" << nm << "\">\n";
    x << in << "    <joint name=\"gripper:" << nm << "\" type=\"slide\" axis=\"0 " << sgn << " 0\" range=\"0 "
      << Num{opt.finger_max} << "\"/>\n";
    x << in << "    <geom name=\"gripper:" << nm << "\" type=\"box\" size=\"" << v3(0.012, kFingerPad / 2, fh)
      << "\" pos=\"" << v3(0, sgn * kFingerPad / 2, fz) << "\" mass=\"0.05\" friction=\"" << Num{opt.friction}
      << " 0.005 0.0001\" rgba=\"0.3 0.3 0.33 1\"/>\n";
    x << in << "  </body>\n";
  }
  x << in << "</body>\n";
  return x.str();
}

}  // namespace

// The scene's default colours by class (class_colours.hpp).
std::array<double, 3> class_colour(const world::Scenario& s, const std::string& cls) {
  return class_colours(s, cls).at(cls);
}

std::array<double, 3> region_colour(std::size_t i) {
  static const std::array<std::array<double, 3>, 6> palette{{
      {0.20, 0.60, 0.25}, {0.25, 0.45, 0.80}, {0.80, 0.55, 0.20},
      {0.60, 0.30, 0.60}, {0.30, 0.65, 0.65}, {0.70, 0.70, 0.25},
  }};
  return palette[i % palette.size()];
}

std::string mujoco_camera_name(const std::string& camera) { return "camera:" + camera; }

world::Vec3 parking_position(int index) { return {3.0 + 0.5 * index, 3.0, -3.0}; }

double object_base_z(const world::Scenario& s, const world::Object& o) {
  double z = o.position[2];
  for (const auto& c : s.containers) {
    if (std::abs(o.position[0] - c.position[0]) <= c.size[0] / 2 &&
        std::abs(o.position[1] - c.position[1]) <= c.size[1] / 2)
      z = std::max(z, c.position[2] + kTrayPlate);
  }
  return z + o.size[2] / 2;
}

std::string build_mjcf(const world::Scenario& s, const MjcfOptions& opt) {
  const std::string_view ur5 = ur5_model_mjcf();
  for (const auto& r : s.regions) check_name(r.name, r.where);
  for (const auto& c : s.containers) check_name(c.name, c.where);
  for (const auto& o : s.objects) check_name(o.name, o.where);

  // Extent of everything on the table, for the table top and the camera.
  const world::TableTop top = world::table_top(s);
  const double xmin = top.xmin, xmax = top.xmax, ymin = top.ymin, ymax = top.ymax;
  const double cx = (xmin + xmax) / 2, cy = (ymin + ymax) / 2;

  const int nthings = static_cast<int>(s.objects.size() + s.containers.size()) + opt.spare_blocks + opt.spare_trays;
  const int nconmax = std::max(150, 12 * nthings + 60);
  const int njmax = 6 * nconmax + 200;
  const int nstack = std::max(400000, 60 * njmax + 200000);

  std::ostringstream x;
  x << "<mujoco model=\"rtamp:" << xml_escape(s.name) << "\">\n";
  x << "  <compiler angle=\"radian\" autolimits=\"true\"/>\n";
  x << "  <option timestep=\"" << Num{opt.timestep} << "\" integrator=\"Euler\" cone=\"pyramidal\"/>\n";
  x << "  <custom>" << model_section(ur5, "custom") << "</custom>\n";
  x << "  <size njmax=\"" << njmax << "\" nconmax=\"" << nconmax << "\" nstack=\"" << nstack << "\"/>\n";
  // The offscreen buffer holds the largest camera image (and the default 640x480 pictures).
  const std::vector<world::Camera> cameras = world::cameras_of(s);
  int offwidth = 640, offheight = 480;
  for (const world::Camera& c : cameras) offwidth = std::max(offwidth, c.width), offheight = std::max(offheight, c.height);
  x << "  <visual><global offwidth=\"" << offwidth << "\" offheight=\"" << offheight << "\"/>"
       "<quality shadowsize=\"2048\"/><headlight ambient=\"0.25 0.25 0.25\" diffuse=\"0.2 0.2 0.2\" specular=\"0.1 0.1 0.1\"/>"
       "<map znear=\"0.01\"/></visual>\n";
  x << "  <default>\n"
       "    <geom contype=\"1\" conaffinity=\"3\" friction=\""
    << Num{opt.friction} << " 0.005 0.0001\" solref=\"0.01 1\"/>\n"
    << "    <default class=\"gripper\"><geom contype=\"2\" conaffinity=\"1\" rgba=\"0.15 0.15 0.17 1\"/>"
       "<joint armature=\"0.01\" damping=\"10\"/></default>\n"
       "    <default class=\"visual\"><geom contype=\"0\" conaffinity=\"0\" group=\"1\"/></default>\n"
    << model_section(ur5, "default") << "  </default>\n";
  x << "  <worldbody>\n";
  x << "    <light name=\"sun\" pos=\"" << v3(cx, cy, 3) << "\" dir=\"0 0.2 -1\" directional=\"true\" castshadow=\"false\" diffuse=\"0.5 0.5 0.5\" specular=\"0.1 0.1 0.1\"/>\n";
  x << "    <geom name=\"floor\" type=\"plane\" size=\"5 5 0.1\" pos=\"0 0 -0.75\" rgba=\"0.82 0.83 0.85 1\" class=\"visual\"/>\n";
  x << "    <geom name=\"table\" type=\"box\" size=\"" << v3((xmax - xmin) / 2, (ymax - ymin) / 2, 0.025)
    << "\" pos=\"" << v3(cx, cy, -0.025) << "\" rgba=\"0.93 0.91 0.86 1\"/>\n";
  for (std::size_t i = 0; i < s.regions.size(); ++i) {
    const auto& r = s.regions[i];
    auto c = region_colour(i);
    const std::string n = xml_escape(r.name);
    const double hx = r.size[0] / 2, hy = r.size[1] / 2, t = 0.006;
    x << "    <geom name=\"region:" << n << "\" class=\"visual\" type=\"box\" size=\"" << v3(hx, hy, 0.0005)
      << "\" pos=\"" << v3(r.center[0], r.center[1], r.center[2] + 0.0005) << "\" rgba=\""
      << v4(0.5 + 0.5 * c[0], 0.5 + 0.5 * c[1], 0.5 + 0.5 * c[2], 1) << "\"/>\n";
    for (int sgn : {-1, 1}) {
      x << "    <geom name=\"region:" << n << "/edge_y" << sgn << "\" class=\"visual\" type=\"box\" size=\""
        << v3(hx, t, 0.0008) << "\" pos=\"" << v3(r.center[0], r.center[1] + sgn * (hy - t), r.center[2] + 0.0008)
        << "\" rgba=\"" << v4(c[0], c[1], c[2], 1) << "\"/>\n";
      x << "    <geom name=\"region:" << n << "/edge_x" << sgn << "\" class=\"visual\" type=\"box\" size=\""
        << v3(t, hy, 0.0008) << "\" pos=\"" << v3(r.center[0] + sgn * (hx - t), r.center[1], r.center[2] + 0.0008)
        << "\" rgba=\"" << v4(c[0], c[1], c[2], 1) << "\"/>\n";
    }
  }

  // Camera: in front of the table (−x side of the robot is behind it), elevated, looking
  // at the table centre. Axes: x_cam horizontal, z_cam pointing back from the scene.
  {
    const double span = std::max(xmax - xmin, ymax - ymin);
    const double yaw = s.robot.yaw;
    // View from the side opposite the robot base, along the base -> table-centre direction.
    double dx = cx - s.robot.base[0], dy = cy - s.robot.base[1];
    double dn = std::hypot(dx, dy);
    if (dn < 1e-6) dx = std::cos(yaw), dy = std::sin(yaw), dn = 1;
    dx /= dn, dy /= dn;
    const double dist = 0.55 * span + 0.45, height = 0.5 * span + 0.55;
    const double px = cx + dx * dist, py = cy + dy * dist, pz = height;
    double vx = cx - px, vy = cy - py, vz = 0.15 - pz;
    double vn = std::sqrt(vx * vx + vy * vy + vz * vz);
    vx /= vn, vy /= vn, vz /= vn;
    // x_cam = v × up, normalised; y_cam = x_cam × v.
    double ax = vy, ay = -vx, az = 0;
    double an = std::hypot(ax, ay);
    ax /= an, ay /= an;
    double bx = ay * vz - az * vy, by = az * vx - ax * vz, bz = ax * vy - ay * vx;
    x << "    <camera name=\"overview\" pos=\"" << v3(px, py, pz) << "\" xyaxes=\"" << v3(ax, ay, az) << ' '
      << v3(bx, by, bz) << "\" fovy=\"45\"/>\n";
  }

  // The scenario's cameras (world/camera.hpp): MuJoCo's camera frame is OpenCV's with y
  // and z negated (x right, y up, looking along -z).
  std::string wrist_cameras;
  for (const world::Camera& c : cameras) {
    const std::string head = "<camera name=\"" + mujoco_camera_name(c.name) + "\" pos=\"" +
                             v3(c.position[0], c.position[1], c.position[2]) + "\" xyaxes=\"";
    std::ostringstream fov;
    fov << "\" fovy=\"" << Num{c.fovy} << "\"/>\n";
    if (c.mount == world::Camera::Mount::Wrist) {
      wrist_cameras += "                    " + head + "1 0 0 0 -1 0" + fov.str();
      continue;
    }
    const auto axes = world::fixed_camera_axes(c);
    x << "    " << head << v3(axes[0][0], axes[0][1], axes[0][2]) << ' ' << v3(-axes[1][0], -axes[1][1], -axes[1][2])
      << fov.str();
  }

  // The arm: the UR5's model file, on a mount at the scenario's base pose, with the
  // gripper inside its flange body.
  const std::string gripper = gripper_mjcf(opt);
  std::string arm(model_section(ur5, "worldbody"));
  const auto flange = arm.find("<body name=\"ur5:flange\"");
  if (flange == std::string::npos) throw Error("the UR5 model has no body 'ur5:flange'");
  arm.insert(arm.find('>', flange) + 1, "\n" + gripper + wrist_cameras);
  const double ry = s.robot.yaw;
  x << "    <body name=\"ur5:mount\" pos=\"" << v3(s.robot.base[0], s.robot.base[1], s.robot.base[2]) << "\" quat=\""
    << v4(std::cos(ry / 2), 0, 0, std::sin(ry / 2)) << "\">\n"
    << arm << "    </body>\n";

  // Movable bodies.
  auto block_body = [&](const std::string& bname, const world::Vec3& pos, const world::Vec3& size,
                        const std::array<double, 3>& rgb, bool parked) {
    x << "    <body name=\"" << xml_escape(bname) << "\" pos=\"" << v3(pos[0], pos[1], pos[2]) << "\">\n";
    x << "      <freejoint name=\"" << xml_escape(bname) << "\"/>\n";
    x << "      <geom name=\"" << xml_escape(bname) << "\" type=\"box\" size=\""
      << v3(size[0] / 2, size[1] / 2, size[2] / 2) << "\" mass=\"" << Num{opt.block_mass} << "\" rgba=\""
      << v4(rgb[0], rgb[1], rgb[2], 1) << "\"" << (parked ? " contype=\"0\" conaffinity=\"0\"" : "") << "/>\n";
    x << "    </body>\n";
  };
  auto tray_body = [&](const std::string& bname, const world::Vec3& pos, const world::Vec3& size,
                       const std::array<double, 3>& rgb, bool parked) {
    x << "    <body name=\"" << xml_escape(bname) << "\" pos=\"" << v3(pos[0], pos[1], pos[2]) << "\">\n";
    x << "      <freejoint name=\"" << xml_escape(bname) << "\"/>\n";
    tray_geoms(x, size, rgb, opt.tray_mass, parked ? " contype=\"0\" conaffinity=\"0\"" : "", xml_escape(bname));
    x << "    </body>\n";
  };
  std::vector<std::string> movable;
  for (const auto& c : s.containers) {
    tray_body("ctr:" + c.name, c.position, c.size, class_colour(s, c.cls), false);
    movable.push_back("ctr:" + c.name);
  }
  for (const auto& o : s.objects) {
    block_body("obj:" + o.name, {o.position[0], o.position[1], object_base_z(s, o)}, o.size, class_colour(s, o.cls),
               false);
    movable.push_back("obj:" + o.name);
  }
  int park = 0;
  for (int k = 0; k < opt.spare_blocks; ++k) {
    block_body("spare_block:" + std::to_string(k), parking_position(park++), opt.spare_block_size,
               class_colour(s, "block"), true);
    movable.push_back("spare_block:" + std::to_string(k));
  }
  for (int k = 0; k < opt.spare_trays; ++k) {
    tray_body("spare_tray:" + std::to_string(k), parking_position(park++), opt.spare_tray_size, class_colour(s, "tray"),
              true);
    movable.push_back("spare_tray:" + std::to_string(k));
  }
  x << "  </worldbody>\n";

  x << "  <equality>\n";
  for (const auto& b : movable)
    x << "    <weld name=\"grasp:" << xml_escape(b) << "\" body1=\"gripper\" body2=\"" << xml_escape(b)
      << "\" active=\"false\" solref=\"0.01 1\"/>\n";
  x << "  </equality>\n";

  x << "  <actuator>" << model_section(ur5, "actuator");
  for (const char* nm : {"left", "right"})
    x << "    <position name=\"gripper:" << nm << "\" joint=\"gripper:" << nm << "\" kp=\"400\" ctrlrange=\"0 "
      << Num{opt.finger_max} << "\" forcelimited=\"true\" forcerange=\"-15 15\"/>\n";
  x << "  </actuator>\n";

  x << "  <keyframe>\n    <key name=\"home\" qpos=\"";
  for (int i = 0; i < 6; ++i) x << Num{opt.home[i]} << ' ';
  x << Num{opt.finger_max} << ' ' << Num{opt.finger_max};
  // Free joints keep their body positions (qpos0): position + identity quaternion.
  auto freeq = [&](const world::Vec3& p) { x << ' ' << v3(p[0], p[1], p[2]) << " 1 0 0 0"; };
  for (const auto& c : s.containers) freeq(c.position);
  for (const auto& o : s.objects) freeq({o.position[0], o.position[1], object_base_z(s, o)});
  for (int k = 0; k < park; ++k) freeq(parking_position(k));
  x << "\" ctrl=\"";
  for (int i = 0; i < 6; ++i) x << Num{opt.home[i]} << ' ';
  x << Num{opt.finger_max} << ' ' << Num{opt.finger_max} << "\"/>\n  </keyframe>\n";
  x << "</mujoco>\n";
  return x.str();
}

}  // namespace rtamp::sim
