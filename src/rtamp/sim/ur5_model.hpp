// The UR5's MuJoCo model: the text of models/ur5.xml, compiled into the library
// (src/rtamp/sim/embed_model.cmake) so that nothing is read from disk at run time; the
// same file is installed as share/rtamp/models/ur5.xml (docs/robot.md "The model file").
// build_mjcf splices it into a scenario's world (mjcf_builder.hpp).
// Invariant: the text is a complete MJCF model that MuJoCo loads on its own; its DH
// offsets and joint ranges are the ones robot::DhParameters::ur5() and
// robot::JointLimits::ur5() are generated from.
#pragma once

#include <string_view>

namespace rtamp::sim {

// The model file's text (models/ur5.xml), byte for byte.
std::string_view ur5_model_mjcf();

}  // namespace rtamp::sim
