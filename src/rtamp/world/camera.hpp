// A camera of the scenario (docs/scenario.md "cameras", docs/perception.md): where it
// is (fixed in the world, or on the UR5's flange), what it images (resolution,
// vertical field of view, depth range), how often, and the noise of its depth.
// A scenario that lists no cameras gets default_cameras(): a fixed camera above the
// table that sees every region, and a wrist camera with an Intel D435's depth field
// of view (87° x 58°) and range (0.3-3 m).
//
// Frames are OpenCV's: x right, y down, z forward (the optical axis). A fixed camera
// looks from `position` at `look_at` with the world's z up in its image (straight
// down: the world's +x is up in the image); a wrist camera sits at `position` in the
// flange frame and looks along the tool axis (flange z), its image x along flange x.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "rtamp/util/error.hpp"

namespace rtamp::world {

using Vec3 = std::array<double, 3>;
struct Scenario;

// Depth noise: per pixel, independent Gaussian noise of standard deviation a + b z²
// (z the depth in m), then rounding to quantum_mm millimetres; a pixel at a depth
// edge (a 4-neighbour more than kEdgeJump nearer or farther) reads no depth (0) with
// probability edge_dropout.
struct DepthNoise {
  double a = 0.0005;          // m
  double b = 0.0015;          // 1/m
  double quantum_mm = 1.0;    // 0: no rounding
  double edge_dropout = 0.3;  // probability in [0, 1]
  static constexpr double kEdgeJump = 0.01;  // m
};

struct Camera {
  enum class Mount { Fixed, Wrist };
  std::string name;
  Mount mount = Mount::Fixed;
  Vec3 position{0, 0, 1};  // Fixed: world; Wrist: flange frame
  Vec3 look_at{0, 0, 0};   // Fixed only: the world point on the optical axis
  int width = 640, height = 480;
  double fovy = 45;        // vertical field of view, degrees
  double near = 0.1, far = 3.0;  // depth range (m): outside it a pixel reads 0
  double rate = 10;        // frames per second of world time
  DepthNoise noise;
  SourceLocation where;
};

// Limits the validator enforces.
inline constexpr int kMinCameraPixels = 16, kMaxCameraPixels = 4096;
inline constexpr double kMaxCameraRate = 1000;  // Hz
inline constexpr double kMaxCameraRange = 100;  // m

// A camera of that mount with every field but name, pose and where at its default:
// fixed 640x480, fovy 60°, range 0.1-3 m; wrist (an Intel D435's depth stream)
// 424x240 at fovy 58° (87° across), range 0.3-3 m, 6.5 cm off the tool axis along
// flange x and 2 cm below the flange. Both 10 Hz, DepthNoise's defaults.
Camera default_camera(Camera::Mount mount);
// The scenario's cameras, or default_cameras(s) when it lists none.
std::vector<Camera> cameras_of(const Scenario& s);
// "overhead" (fixed: above the centre of the regions, containers and objects, set
// back from the robot by 15 % of its height, just high enough to see all of them
// with an 8 cm margin) and "wrist".
std::vector<Camera> default_cameras(const Scenario& s);
// The camera named `name`; rtamp::Error "unknown camera 'x' (cameras: a, b)" at `where`.
const Camera& find_camera(const std::vector<Camera>& cameras, const std::string& name, const SourceLocation& where);

// The camera used when none is named: the first fixed camera, else the first one.
const Camera& primary_camera(const std::vector<Camera>& cameras);

// Horizontal field of view (degrees) from the vertical one and the aspect ratio.
double horizontal_fov(const Camera& c);
// A fixed camera's rotation world -> camera (rows: the camera's x, y, z axes in the
// world), OpenCV's convention. Requires position != look_at.
std::array<Vec3, 3> fixed_camera_axes(const Camera& c);
// Whether a fixed camera images world point p: in front, within the depth range,
// inside the image.
bool fixed_camera_sees(const Camera& c, const Vec3& p);

const char* to_string(Camera::Mount m);  // "fixed", "wrist"

}  // namespace rtamp::world
