#pragma once
// Helpers shared by the test/ros tests (the node's library, without a master); SourcePath and RunRunner
// come from the integration tests' helpers.

#include <string>

#include "../integration/helpers/runner.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/io/text_file.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/ros/transform_frames.hpp"

namespace flexmbd {
namespace test {

constexpr char kDoublePendulumUrdf[] = "config/double_pendulum/double_pendulum.urdf";
constexpr char kBeamArmUrdf[] = "test/data/urdf/beam_arm.urdf";

/// The reference case config/double_pendulum/: shoulder at (0, 0, 2) m turning about y, driven from 0 deg;
/// elbow 1 m further along link1, starting at -30 deg.
inline Model DoublePendulum() {
  return BuildModel(
      LoadModelSpec(SourcePath(kDoublePendulumUrdf), SourcePath("config/double_pendulum/double_pendulum.yaml")));
}

/// test/data/{urdf,yaml}/beam_arm.*: beam 'arm' clamped at (0, 0, 1) m along the world x axis, 1 m long, 2 cubic
/// elements (nodes every 1/6 m), carrying the rigid body 'tip' on a hinge at its end.
inline Model BeamArm() {
  return BuildModel(LoadModelSpec(SourcePath(kBeamArmUrdf), SourcePath("test/data/yaml/beam_arm.yaml")));
}

/// The tf tree of `model`, loaded from the URDF at `urdf` (relative to the source tree).
inline ros::FrameTree FramesOf(const std::string& urdf, const Model& model) {
  return ros::UrdfFrameTree(ReadTextFile(SourcePath(urdf), "URDF file"), model);
}

/// The frames `model` sends on /tf.
inline std::vector<ros::TransformFrame> MovingFramesOf(const std::string& urdf, const Model& model) {
  return FramesOf(urdf, model).moving;
}

}  // namespace test
}  // namespace flexmbd
