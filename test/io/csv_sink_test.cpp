// CsvSink (include/flexmbd/io/csv_sink.hpp) when the disk fills up: the failed write throws OutputError
// naming the file, the file keeps whole rows only, and the count of samples the message gives is the count
// of rows in the file. The full disk is a file size cap (RLIMIT_FSIZE) or /dev/full.

#include "flexmbd/io/csv_sink.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../integration/helpers/file_size_limit.hpp"
#include "cut_csv.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/step_context_builder.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace csv_sink_test {

// Far more rows than the cap below takes (a double pendulum row at rest is about 120 bytes, its numbers in their
// shortest round-trip form).
constexpr int kSamplesOffered = 2000;
constexpr rlim_t kCapBytes = 50000;

Model DoublePendulum() {
  return BuildModel(LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/config/double_pendulum/double_pendulum.urdf",
                                  std::string(FLEXMBD_SOURCE_DIR) + "/config/double_pendulum/double_pendulum.yaml"));
}

TEST(CsvSink, DiskFullMidRunKeepsWholeRowsAndCountsThemTruly) {
  const Model model = DoublePendulum();
  const std::string path = testing::TempDir() + "csv_sink_full.csv";
  StepContextBuilder builder(model);
  const State& state = model.initial_state();
  const OutputSample sample = MakeSample(model, state, builder.AtState(state), 0.0, 0);
  std::string message;
  int written = 0;
  {
    const test::FileSizeLimit cap(kCapBytes);
    CsvSink sink(model, path);
    try {
      for (; written < kSamplesOffered; ++written) {
        OutputSample row = sample;
        row.t = 0.01 * written;
        sink.Write(row);
      }
      sink.Close();
    } catch (const OutputError& error) {
      message = error.what();
    }
    EXPECT_NO_THROW(sink.Close());  // the failure was reported once
  }
  ASSERT_LT(written, kSamplesOffered) << "the cap did not stop the run";
  EXPECT_EQ(message.find("output.csv: writing '" + path + "' failed (File too large)"), 0u) << message;
  test::ExpectWholeRowsAsClaimed(path, message);
  EXPECT_LE(test::SamplesClaimed(message), written);  // never more than were offered before the failure
  const std::vector<std::string> lines = test::FileLines(path);
  for (size_t k = 1; k < lines.size(); ++k) EXPECT_DOUBLE_EQ(std::stod(lines[k]), 0.01 * (k - 1)) << "row " << k;
}

TEST(CsvSink, FullDeviceFailsAtCloseSayingNothingWasWritten) {
  // A short run stays in the buffer until Close, which must not claim it.
  const Model model = DoublePendulum();
  StepContextBuilder builder(model);
  const State& state = model.initial_state();
  CsvSink sink(model, "/dev/full");
  sink.Write(MakeSample(model, state, builder.AtState(state), 0.0, 0));
  try {
    sink.Close();
    FAIL() << "Close succeeded on /dev/full";
  } catch (const OutputError& error) {
    EXPECT_EQ(std::string(error.what()),
              "output.csv: writing '/dev/full' failed (No space left on device); the file holds nothing");
  }
}

}  // namespace csv_sink_test
}  // namespace flexmbd
