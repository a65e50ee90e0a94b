#include "rtamp/sim/camera_perception.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/util/error.hpp"

namespace rtamp::sim {

struct CameraPerception::Eye {
  std::size_t rig_index;
  CameraDetector detector;
  DepthVisibility visibility;
  CameraImage image;
  bool seen = false;  // a frame was taken
};

// Camera k's frame, and where it cannot see, the other cameras' last frames.
class CameraPerception::Views : public world::Visibility {
 public:
  Views(const std::vector<std::unique_ptr<Eye>>& eyes, std::size_t k) : eyes_(eyes), k_(k) {}
  world::Sight sight(const world::BelievedThing& t) const override {
    const world::Sight s = eyes_[k_]->visibility.sight(t);
    if (s != world::Sight::OutOfView) return s;
    for (std::size_t j = 0; j < eyes_.size(); ++j)
      if (j != k_ && eyes_[j]->seen && eyes_[j]->visibility.sight(t) != world::Sight::OutOfView)
        return world::Sight::Elsewhere;
    return world::Sight::OutOfView;
  }

 private:
  const std::vector<std::unique_ptr<Eye>>& eyes_;
  std::size_t k_;
};

CameraPerception::CameraPerception(const Simulation& sim, CameraPerceptionOptions options)
    : sim_(sim), rig_(sim, world::cameras_of(sim.scenario()), options.seed), belief_(sim.scenario(), options.belief) {
  if (options.cameras.empty()) options.cameras.push_back(world::primary_camera(rig_.cameras()).name);
  for (std::size_t i = 0; i < options.cameras.size(); ++i) {
    const std::string& name = options.cameras[i];
    if (std::find(options.cameras.begin(), options.cameras.begin() + static_cast<std::ptrdiff_t>(i), name) !=
        options.cameras.begin() + static_cast<std::ptrdiff_t>(i))
      throw Error("camera '" + name + "' is listed twice");
    const std::size_t index = rig_.index(name, {});
    const world::Camera& c = rig_.cameras()[index];
    perceiving_.push_back(c);
    eyes_.push_back(std::make_unique<Eye>(Eye{index, CameraDetector(sim.scenario(), c.noise), DepthVisibility(c.noise), {}}));
  }
}

CameraPerception::~CameraPerception() = default;

const CameraImage& CameraPerception::image() const { return eyes_[last_]->image; }

void CameraPerception::frame() {
  for (std::size_t k = 0; k < eyes_.size(); ++k) frame(k);
}

void CameraPerception::frame(std::size_t k) {
  Eye& eye = *eyes_.at(k);
  rig_.render(eye.rig_index, eye.image, {.noise = false, .segmentation = false});
  ++frames_;
  last_ = k;
  eye.seen = true;
  // The depth noise on the helper thread while this one segments the colours (the two
  // touch different parts of the image); the same image as render(noise) gives.
  auto noise = [&] { rig_.add_noise(eye.rig_index, eye.image); };
  helper_.run(noise);
  {
    const HelperThread::Join join(helper_);  // even if segmenting throws
    eye.detector.segment(eye.image);
  }
  eye.detector.fit(eye.image, detections_);
  eye.visibility.set_frame(eye.image);
  world::Gripper gripper;
  const Eigen::Vector3d tool = sim_.tool_pose().translation();
  gripper.tool = {tool.x(), tool.y(), tool.z()};
  if (sim_.held() != held_) {
    // Just grasped: the believed thing of its class nearest the tool (the one the arm went for).
    held_ = sim_.held();
    held_name_.clear();
    double best = INFINITY;
    if (held_ >= 0)
      for (const auto& t : belief_.things())
        if (t.cls == sim_.thing(held_).cls) {
          const double d = std::hypot(t.base[0] - tool.x(), t.base[1] - tool.y());
          if (d < best) best = d, held_name_ = t.name;
        }
  }
  gripper.holds = held_name_;
  const Simulation::FailedGrasp& failed = sim_.last_failed_grasp();
  gripper.failed_grasp_at = failed.time;
  gripper.failed_grasp_tool = {failed.tool.x(), failed.tool.y(), failed.tool.z()};
  gripper.failed_grasp_empty = failed.empty;
  belief_.update(sim_.time(), detections_, Views(eyes_, k), gripper);
}

}  // namespace rtamp::sim
