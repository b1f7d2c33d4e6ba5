#include "flexmbd/ros/sample_fan_out.hpp"

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace ros {

SampleFanOut::SampleFanOut(const Model& model, RecordingFiles files, TopicNames topics,
                           tf2_msgs::TFMessage static_transforms)
    : model_(model),
      files_(std::move(files)),
      topics_(std::move(topics)),
      static_transforms_(std::move(static_transforms)) {
  OpenRecordings();
}

void SampleFanOut::AddLiveSink(std::unique_ptr<MessageSink> sink) { live_sinks_.push_back(std::move(sink)); }

void SampleFanOut::Write(const OutputSample& sample, const SampleMessages& messages) {
  for (const auto& sink : live_sinks_) sink->Write(messages);
  try {
    if (bag_) bag_->Write(messages);
    if (csv_) csv_->Write(sample);
  } catch (const OutputError& failure) {
    const std::string others = CloseEachRecording();
    throw OutputError(others.empty() ? failure.what() : failure.what() + ("; " + others));
  }
}

void SampleFanOut::EndBatch() {
  for (const auto& sink : live_sinks_) sink->EndBatch();
}

void SampleFanOut::RestartRecordings() {
  CloseRecordings();
  OpenRecordings();
}

void SampleFanOut::Close() {
  for (const auto& sink : live_sinks_) sink->Close();
  CloseRecordings();
}

void SampleFanOut::OpenRecordings() {
  if (!files_.bag.empty()) {
    bag_ = std::make_unique<BagSink>(files_.bag, files_.bag_compression, topics_, ToBodyMarkers(model_),
                                     static_transforms_);
  }
  if (!files_.csv.empty()) csv_ = std::make_unique<CsvSink>(model_, files_.csv);
}

void SampleFanOut::CloseRecordings() {
  const std::string failures = CloseEachRecording();
  if (!failures.empty()) throw OutputError(failures);
}

std::string SampleFanOut::CloseEachRecording() {
  std::string failures;
  const auto close = [&failures](auto* sink) {
    if (!*sink) return;
    try {
      (*sink)->Close();
    } catch (const OutputError& failure) {
      failures += (failures.empty() ? "" : "; ") + std::string(failure.what());
    }
    sink->reset();
  };
  close(&bag_);
  close(&csv_);
  return failures;
}

}  // namespace ros
}  // namespace flexmbd
