#include "flexmbd/ros/sample_converter.hpp"

namespace flexmbd {
namespace ros {

SampleConverter::SampleConverter(const Model& model, std::string world_frame)
    : model_(model), world_frame_(std::move(world_frame)) {}

SampleMessages SampleConverter::Convert(const OutputSample& sample, const State& state) {
  SampleMessages messages{ToJointState(model_, sample), ToEnergy(sample), ToJointReactions(model_, sample),
                          ToSolverStep(sample), std::nullopt};
  messages.joint_state.header.seq = messages.energy.header.seq = messages.reactions.header.seq =
      messages.solver.header.seq = next_seq_++;
  if (!last_transform_time_ || state.t > *last_transform_time_) {
    messages.transforms = ToLinkTransforms(model_, state, world_frame_);
    last_transform_time_ = state.t;
  }
  return messages;
}

}  // namespace ros
}  // namespace flexmbd
