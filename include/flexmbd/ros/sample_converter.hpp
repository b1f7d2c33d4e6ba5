#pragma once
/// @file
/// One conversion per sample: SampleConverter turns an OutputSample (and the state it was taken in) into
/// the messages that every sink (topics, bag) receives.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "flexmbd/ros/message_conversions.hpp"

namespace flexmbd {
namespace ros {

/// The messages of one output sample.
struct SampleMessages {
  sensor_msgs::JointState joint_state;
  Energy energy;
  JointReactionArray reactions;
  SolverStep solver;
  /// One entry per stop of the model; with none (a model without stops) the message is neither published
  /// nor recorded.
  JointContactArray contacts;
  /// One entry per frictional joint; with none, neither published nor recorded.
  JointFrictionArray friction;
  /// One entry per station of output.beam_stations; with none, neither published nor recorded.
  BeamLoadsArray beam_loads;
  /// One entry per aero section (aero.sections) and per strip station (output.strip_stations); with neither,
  /// neither published nor recorded.
  AeroLoadsArray aero_loads;
  /// Link and beam node frames at the state's time, when has_transforms. A sample is interpolated inside the
  /// step that ends at the state, so transforms are stamped with the state's own time (exact poses) and sent
  /// once per such step: stamps then bracket every sample time, and tf interpolates between them.
  bool has_transforms = false;
  tf2_msgs::TFMessage transforms;
};

class SampleConverter {
 public:
  /// @param model must outlive the converter. @param frames its tf tree: the moving frames go on /tf, and
  /// the reactions' header names the world frame.
  SampleConverter(const Model& model, const FrameTree& frames);

  /// Fills `messages` with those of `sample`, taken while the simulation is at `state` (state.t >=
  /// sample.t); `messages` may hold an earlier sample's, whose storage it reuses. Their header.stamp is the
  /// sample's time and header.seq its index in the run (0 first): what roscpp's publisher numbers them on
  /// the wire, so that a bag holds the bytes a subscriber receives.
  void Convert(const OutputSample& sample, const State& state, SampleMessages* messages);

 private:
  const Model& model_;
  std::vector<TransformFrame> frames_;
  std::string world_frame_;
  uint32_t next_seq_ = 0;
  std::optional<double> last_transform_time_;  ///< state time of the last transforms sent [s]
};

}  // namespace ros
}  // namespace flexmbd
