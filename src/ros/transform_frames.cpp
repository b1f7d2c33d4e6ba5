#include "flexmbd/ros/transform_frames.hpp"

namespace flexmbd {
namespace ros {

std::string BeamNodeFrameName(const std::string& beam, size_t k) { return beam + "/node_" + std::to_string(k); }

std::vector<TransformFrame> TransformFrames(const Model& model) {
  std::vector<TransformFrame> frames;
  for (const BodyInfo& body : model.bodies()) frames.push_back(TransformFrame{body.name, body.node, body.p_NBo_N});
  for (const BeamInfo& beam : model.beams()) {
    for (size_t k = 0; k < beam.nodes.size(); ++k) {
      frames.push_back(TransformFrame{BeamNodeFrameName(beam.name, k), beam.nodes[k], Vec3::Zero()});
    }
  }
  return frames;
}

}  // namespace ros
}  // namespace flexmbd
