// AsyncSampleWriter (include/flexmbd/ros/async_sample_writer.hpp): every sample written in order, records
// recycled, a sink's error passed back to the run loop.

#include "flexmbd/ros/async_sample_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <stdexcept>

#include "ros_test_util.hpp"

namespace flexmbd {
namespace ros {
namespace async_sample_writer_test {

// A live sink that keeps the sequence numbers it is given and, for each EndBatch, how many it had been
// given by then (read after Flush, which orders the threads).
class SeqSink : public MessageSink {
 public:
  SeqSink(std::vector<uint32_t>* written, std::vector<size_t>* batch_ends, long fail_at)
      : written_(written), batch_ends_(batch_ends), fail_at_(fail_at) {}
  void Write(const SampleMessages& messages) override {
    if (static_cast<long>(written_->size()) == fail_at_) throw std::runtime_error("disk full");
    written_->push_back(messages.joint_state.header.seq);
  }
  void EndBatch() override {
    if (batch_ends_) batch_ends_->push_back(written_->size());
  }

 private:
  std::vector<uint32_t>* written_;
  std::vector<size_t>* batch_ends_;
  long fail_at_;
};

// A fan-out without recording files, writing to a SeqSink.
SampleFanOut FanOutTo(const Model& model, std::vector<uint32_t>* written, long fail_at = -1,
                      std::vector<size_t>* batch_ends = nullptr) {
  SampleFanOut outputs(model, RecordingFiles{}, DefaultTopicNames(), tf2_msgs::TFMessage());
  outputs.AddLiveSink(std::make_unique<SeqSink>(written, batch_ends, fail_at));
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

TEST(AsyncSampleWriter, EndsEveryBatchBeforeFlushReturns) {
  // The topics wake roscpp's sender at a batch's end (TopicPublisher::EndBatch): a sample written after the
  // last EndBatch would wait in roscpp's queue until the next run's samples came.
  const Model model = test::DoublePendulum();
  std::vector<uint32_t> written;
  std::vector<size_t> batch_ends;
  SampleFanOut outputs = FanOutTo(model, &written, -1, &batch_ends);
  AsyncSampleWriter writer(&outputs, 64);
  for (uint32_t k = 0; k < 150; ++k) SubmitSeq(&writer, k);
  writer.Flush();
  ASSERT_FALSE(batch_ends.empty());
  EXPECT_EQ(batch_ends.back(), 150u);
  EXPECT_TRUE(std::is_sorted(batch_ends.begin(), batch_ends.end()));
  // a lone sample, handed over by Flush
  SubmitSeq(&writer, 150);
  writer.Flush();
  EXPECT_EQ(batch_ends.back(), 151u);
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

TEST(AsyncSampleWriter, SinkErrorReachesTheRunLoopOnceAndLaterSamplesAreDropped) {
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
  // the run has ended: what the run loop still hands over (a node flushing its pending samples) is dropped,
  // and the cleanup's Flush returns instead of throwing the same failure again
  for (uint32_t k = 5; k < 10; ++k) SubmitSeq(&writer, k);
  EXPECT_NO_THROW(writer.Flush());
  EXPECT_EQ(written, (std::vector<uint32_t>{0, 1, 2}));
}

}  // namespace async_sample_writer_test
}  // namespace ros
}  // namespace flexmbd
