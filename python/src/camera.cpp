// Python bindings of a MuJoCo world's cameras (sim/camera_rig.hpp, docs/perception.md):
// rtamp.Camera renders one of the scenario's cameras from the world's current state and
// returns a rtamp.CameraFrame whose images are NumPy arrays (RGB, metric depth, the
// segmentation pass), with OpenCV intrinsics and extrinsics and the depth's point cloud.
// Invariants: arrays are copies owned by Python (a frame outlives the next render);
// rendering releases the GIL; a Camera keeps its world alive.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>

#include <optional>

#include "bindings.hpp"
#include "rtamp/episode/sim_world.hpp"
#include "rtamp/sim/camera_rig.hpp"

namespace rtamp::python {

namespace {

struct PyFrame {
  sim::CameraImage image;
  std::string camera;
  double time = 0;
  bool segmentation = false;
};

class PyCamera {
 public:
  PyCamera(episode::SimWorld& world, const std::optional<std::string>& name, std::uint64_t seed)
      : world_(world),
        rig_(world.session().sim(), world::cameras_of(world.session().sim().scenario()), seed),
        index_(rig_.index(name ? *name : world::primary_camera(rig_.cameras()).name, {})) {}

  PyFrame render(bool segmentation, bool noise) {
    PyFrame f;
    f.camera = rig_.cameras()[index_].name;
    f.segmentation = segmentation;
    f.time = world_.session().sim().time();
    rig_.render(index_, f.image, {.noise = noise, .segmentation = segmentation});
    return f;
  }
  const world::Camera& camera() const { return rig_.cameras()[index_]; }
  sim::Intrinsics intrinsics() const { return rig_.intrinsics(index_); }

 private:
  episode::SimWorld& world_;
  sim::CameraRig rig_;
  std::size_t index_;
};

template <class T>
py::array_t<T> image_array(const std::vector<T>& data, int height, int width, int channels) {
  std::vector<py::ssize_t> shape{height, width};
  if (channels > 1) shape.push_back(channels);
  py::array_t<T> a(shape);
  std::copy(data.begin(), data.end(), a.mutable_data());
  return a;
}

Eigen::Matrix3d camera_matrix(const sim::Intrinsics& k) {
  Eigen::Matrix3d m;
  m << k.fx, 0, k.cx, 0, k.fy, k.cy, 0, 0, 1;
  return m;
}

Eigen::Matrix4d world_to_camera(const sim::Extrinsics& e) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = e.R;
  m.topRightCorner<3, 1>() = e.t;
  return m;
}

// World points of every pixel with a depth reading (row-major order), N x 3.
py::array_t<double> point_cloud(const sim::CameraImage& im) {
  std::vector<double> pts;
  for (int v = 0; v < im.height; ++v)
    for (int u = 0; u < im.width; ++u) {
      const float z = im.depth[static_cast<std::size_t>(v) * static_cast<std::size_t>(im.width) + static_cast<std::size_t>(u)];
      if (!(z > 0)) continue;
      const Eigen::Vector3d w = im.extrinsics.to_world(im.intrinsics.back_project(u, v, z));
      pts.insert(pts.end(), {w.x(), w.y(), w.z()});
    }
  py::array_t<double> a(std::vector<py::ssize_t>{static_cast<py::ssize_t>(pts.size() / 3), 3});
  std::copy(pts.begin(), pts.end(), a.mutable_data());
  return a;
}

}  // namespace

void bind_camera(py::module_& m) {
  py::class_<PyFrame>(m, "CameraFrame",
                      "One rendered frame of a camera (docs/perception.md): NumPy arrays, top row first, and the\n"
                      "pinhole model in OpenCV's convention (x right, y down, z forward).")
      .def_readonly("camera", &PyFrame::camera, "The camera's name.")
      .def_readonly("time", &PyFrame::time, "World time of the frame (s).")
      .def_property_readonly(
          "rgb", [](const PyFrame& f) { return image_array(f.image.rgb, f.image.height, f.image.width, 3); },
          "uint8 array (height, width, 3).")
      .def_property_readonly(
          "depth", [](const PyFrame& f) { return image_array(f.image.depth, f.image.height, f.image.width, 1); },
          "float32 array (height, width): metres along the optical axis, noise applied; 0 = no reading.")
      .def_property_readonly(
          "segmentation",
          [](const PyFrame& f) -> py::object {
            if (!f.segmentation) return py::none();
            return image_array(f.image.body, f.image.height, f.image.width, 1);
          },
          "int32 array (height, width) of MuJoCo body ids (-1 background) from the segmentation pass, or\n"
          "None unless render(segmentation=True). The simulator's truth: for scoring perception, not for it.")
      .def_property_readonly("K", [](const PyFrame& f) { return camera_matrix(f.image.intrinsics); },
                             "The 3x3 camera matrix [[fx, 0, cx], [0, fy, cy], [0, 0, 1]].")
      .def_property_readonly("world_to_camera", [](const PyFrame& f) { return world_to_camera(f.image.extrinsics); },
                             "The 4x4 transform of world points into the camera frame (p_cam = R p + t).")
      .def("points", [](const PyFrame& f) { return point_cloud(f.image); },
           "The depth image back-projected into the world: float64 array (N, 3), one row per pixel with a\n"
           "reading, in row-major pixel order.")
      .def("__repr__", [](const PyFrame& f) {
        return "<rtamp.CameraFrame " + f.camera + " " + std::to_string(f.image.width) + "x" +
               std::to_string(f.image.height) + " at " + std::to_string(f.time) + " s>";
      });

  py::class_<PyCamera>(m, "Camera",
                       "One of a MujocoWorld's cameras (the scenario's `cameras:`, else overhead and wrist),\n"
                       "rendered headless with EGL. camera=None is the primary camera. seed: the depth noise's.")
      .def(py::init([](episode::SimWorld& w, const std::optional<std::string>& camera, std::uint64_t seed) {
             py::gil_scoped_release release;
             return std::make_unique<PyCamera>(w, camera, seed);
           }),
           py::arg("world"), py::arg("camera") = py::none(), py::kw_only(), py::arg("seed") = 1, py::keep_alive<1, 2>())
      .def_property_readonly("name", [](const PyCamera& c) { return c.camera().name; }, "The camera's name.")
      .def_property_readonly("resolution", [](const PyCamera& c) { return std::pair{c.camera().width, c.camera().height}; },
                             "(width, height) in pixels.")
      .def_property_readonly("K", [](const PyCamera& c) { return camera_matrix(c.intrinsics()); },
                             "The 3x3 camera matrix.")
      .def("render", &PyCamera::render, py::arg("segmentation") = false, py::arg("noise") = true,
           py::call_guard<py::gil_scoped_release>(),
           "Renders the camera at the world's current state: a CameraFrame (RGB, depth with the camera's\n"
           "noise unless noise=False, and the segmentation pass if segmentation=True).");
}

}  // namespace rtamp::python
