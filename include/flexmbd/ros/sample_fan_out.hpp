#pragma once
/// @file
/// One conversion, several sinks: SampleFanOut hands the messages of each sample to every message sink
/// (topics, bag) and the sample itself to the CSV.

#include <memory>
#include <string>
#include <vector>

#include "flexmbd/io/csv_sink.hpp"
#include "flexmbd/ros/bag_sink.hpp"
#include "flexmbd/ros/message_sink.hpp"

namespace flexmbd {
namespace ros {

/// Files that record every sample of a run; an empty path means none.
struct RecordingFiles {
  std::string bag;
  BagCompression bag_compression = BagCompression::kNone;
  std::string csv;
};

class SampleFanOut {
 public:
  /// Opens the recording files (the node and the runner share this, so they write the same bag and CSV);
  /// the bag starts with `static_transforms` (ToStaticTransforms). `model` must outlive the fan-out. Throws
  /// ConfigError naming a path that cannot be opened, OutputError if a file cannot be written.
  SampleFanOut(const Model& model, RecordingFiles files, TopicNames topics,
               tf2_msgs::TFMessage static_transforms);

  /// Adds a sink that lives across runs (the topics).
  void AddLiveSink(std::unique_ptr<MessageSink> sink);

  /// Writes `sample` to the CSV and `messages` (its conversion) to the message sinks; `messages` may be empty
  /// when there is none (no bag, no topics). A recording that cannot be written ends the run: every recording
  /// file is closed (the others complete) and OutputError says what the failed one holds.
  void Write(const OutputSample& sample, const SampleMessages& messages);

  /// Ends a batch of Writes (MessageSink::EndBatch): what the live sinks held back goes out.
  void EndBatch();

  /// Closes the recording files and opens them again, empty, for a new run from the initial state.
  void RestartRecordings();

  /// Closes the recording files: they are complete and readable afterwards; later samples are not recorded.
  /// Throws OutputError, after closing every file, if one could not be completed.
  void CloseRecordings();

  /// Closes every sink; throws as CloseRecordings does.
  void Close();

 private:
  void OpenRecordings();
  /// Closes every recording file, even when one fails; returns the failures' messages ("; "-separated, empty
  /// if none).
  std::string CloseEachRecording();

  const Model& model_;
  RecordingFiles files_;
  TopicNames topics_;
  tf2_msgs::TFMessage static_transforms_;
  std::vector<std::unique_ptr<MessageSink>> live_sinks_;
  std::unique_ptr<BagSink> bag_;
  std::unique_ptr<CsvSink> csv_;
};

}  // namespace ros
}  // namespace flexmbd
