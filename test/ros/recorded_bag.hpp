#pragma once
// A whole run of a model written to a bag sample by sample, as the node's writer does, for the tests of what a
// bag holds.

#include <string>
#include <vector>

#include "flexmbd/ros/bag_sink.hpp"
#include "flexmbd/ros/sample_converter.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "ros_test_util.hpp"

namespace flexmbd {
namespace test {

/// What a run sampled and the messages made of each sample, in order.
struct RecordedRun {
  std::vector<OutputSample> samples;
  std::vector<ros::SampleMessages> messages;
};

/// Runs `model` (its tf tree from the URDF at `urdf`, relative to the source tree) to its end and writes every
/// sample to an uncompressed bag at `path` under the default topic names; the bag is closed on return.
inline RecordedRun RecordRunToBag(const Model& model, const std::string& urdf, const std::string& path) {
  ros::SampleConverter converter(model, FramesOf(urdf, model));
  Simulation simulation(model);
  RecordedRun run;
  ros::BagSink bag(path, ros::BagCompression::kNone, ros::DefaultTopicNames(), ros::ToBodyMarkers(model),
                   tf2_msgs::TFMessage());
  simulation.Run([&](const OutputSample& sample) {
    run.samples.push_back(sample);
    run.messages.emplace_back();
    converter.Convert(sample, simulation.state(), &run.messages.back());
    bag.Write(run.messages.back());
  });
  bag.Close();
  return run;
}

}  // namespace test
}  // namespace flexmbd
