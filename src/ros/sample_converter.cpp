#include "flexmbd/ros/sample_converter.hpp"

namespace flexmbd {
namespace ros {

SampleConverter::SampleConverter(const Model& model, const FrameTree& frames)
    : model_(model), frames_(frames.moving), world_frame_(frames.world_frame) {}

void SampleConverter::Convert(const OutputSample& sample, const State& state, SampleMessages* messages) {
  FillJointState(model_, sample, &messages->joint_state);
  FillEnergy(sample, &messages->energy);
  FillJointReactions(model_, sample, &messages->reactions);
  FillSolverStep(sample, &messages->solver);
  FillJointContacts(model_.stops(), sample, &messages->contacts);
  FillJointFriction(model_.frictions(), sample, &messages->friction);
  FillBeamLoads(model_.beam_stations(), sample, &messages->beam_loads);
  FillAeroLoads(model_, sample, &messages->aero_loads);
  const uint32_t seq = next_seq_++;
  const ::ros::Time stamp = ToStamp(sample.t);
  for (std_msgs::Header* header :
       {&messages->joint_state.header, &messages->energy.header, &messages->reactions.header,
        &messages->solver.header, &messages->contacts.header, &messages->friction.header,
        &messages->beam_loads.header, &messages->aero_loads.header}) {
    header->seq = seq;
    header->stamp = stamp;
  }
  messages->reactions.header.frame_id = world_frame_;  // the frame of the forces (msg/JointReactionArray.msg)
  messages->has_transforms = !last_transform_time_ || state.t > *last_transform_time_;
  if (messages->has_transforms) {
    FillTransforms(frames_, state, &messages->transforms);
    last_transform_time_ = state.t;
  }
}

}  // namespace ros
}  // namespace flexmbd
