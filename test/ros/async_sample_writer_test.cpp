// AsyncSampleWriter (include/flexmbd/ros/async_sample_writer.hpp): every sample written in order, records
// recycled, a sink's error passed back to the run loop.

#include "flexmbd/ros/async_sample_writer.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace {

// A live sink that keeps the sequence numbers it is given (read after Flush, which orders the threads).
class SeqSink : public MessageSink {
 public:
  explicit SeqSink(std::vector<uint32_t>* written, long fail_at = -1) : written_(written), fail_at_(fail_at) {}
  void Write(const SampleMessages& messages) override {
    if (static_cast<long>(written_->size()) == fail_at_) throw std::runtime_error("disk full");
    written_->push_back(messages.joint_state.header.seq);
  }

 private:
  std::vector<uint32_t>* written_;
  long fail_at_;
};

// A fan-out without recording files, writing to a SeqSink.
SampleFanOut FanOutTo(const Model& model, std::vector<uint32_t>* written, long fail_at = -1) {
  SampleFanOut outputs(model, RecordingFiles{}, DefaultTopicNames());
  outputs.AddLiveSink(std::make_unique<SeqSink>(written, fail_at));
  return outputs;
}

void SubmitSeq(AsyncSampleWriter* writer, uint32_t seq) {
  AsyncSampleWriter::RecordPtr record = writer->Acquire();
  record->messages.joint_state.header.seq = seq;
  writer->Submit(std::move(record));
}

TEST(AsyncSampleWriter, WritesEverySampleInOrderAcrossBatches) {
  // 150 samples in batches of 64: two full batches and a partial one that only Flush hands over.
  const Model model = test::DoublePendulum();
  std::vector<uint32_t> written;
  SampleFanOut outputs = FanOutTo(model, &written);
  AsyncSampleWriter writer(&outputs, 64);
  std::vector<uint32_t> expected;
  for (uint32_t k = 0; k < 150; ++k) {
    SubmitSeq(&writer, k);
    expected.push_back(k);
  }
  writer.Flush();
  EXPECT_EQ(written, expected);
}

TEST(AsyncSampleWriter, HandsWrittenRecordsBackForReuse) {
  const Model model = test::DoublePendulum();
  std::vector<uint32_t> written;
  SampleFanOut outputs = FanOutTo(model, &written);
  AsyncSampleWriter writer(&outputs, 1);
  AsyncSampleWriter::RecordPtr record = writer.Acquire();
  const SampleRecord* first = record.get();
  writer.Submit(std::move(record));
  writer.Flush();
  EXPECT_EQ(writer.Acquire().get(), first);
}

TEST(AsyncSampleWriter, SinkErrorReachesTheRunLoop) {
  const Model model = test::DoublePendulum();
  std::vector<uint32_t> written;
  SampleFanOut outputs = FanOutTo(model, &written, /*fail_at=*/3);
  AsyncSampleWriter writer(&outputs, 1);
  // the error comes back from a later Submit or from Flush, whichever runs after the failed write
  EXPECT_THROW(
      {
        for (uint32_t k = 0; k < 5; ++k) SubmitSeq(&writer, k);
        writer.Flush();
      },
      std::runtime_error);
  EXPECT_EQ(written, (std::vector<uint32_t>{0, 1, 2}));
}

}  // namespace
}  // namespace ros
}  // namespace flexmbd
