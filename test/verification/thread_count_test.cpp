// Results do not depend on solver.threads (docs/theory.md, "Assembly on several threads"), run the user's way:
// flexmbd_run with threads 1 and 2 writes the same CSV, byte for byte, and prints the same step statistics. With two
// threads the elements are evaluated on two threads and the samples formatted and written on a third. Tolerance:
// none, since every sum is made in the same order.

#include <gtest/gtest.h>

#include <string>

#include "flexmbd/io/text_file.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace thread_count_test {

struct Run {
  std::string csv;    ///< the whole file
  std::string steps;  ///< the runner's "steps: ..." line
};

// Adds `setting` ("key: value") to the top-level map `section` of a YAML text, in block or flow style.
void AddSetting(std::string* yaml, const std::string& section, const std::string& setting) {
  const std::string heading = "\n" + section + ":";
  const size_t at = yaml->find(heading) + heading.size();
  const size_t value = yaml->find_first_not_of(' ', at);
  if ((*yaml)[value] == '{') yaml->insert(value + 1, setting + ", ");
  else yaml->insert(at, "\n  " + setting);
}

// The case (a YAML of the source tree with `solver` and `output` maps) run on `threads` threads.
Run RunOn(const std::string& urdf, const std::string& yaml_path, int threads, const std::string& name) {
  const std::string run_name = name + "_threads" + std::to_string(threads);
  const std::string csv = testing::TempDir() + run_name + ".csv";
  std::string yaml = test::SourceText(yaml_path);
  AddSetting(&yaml, "solver", "threads: " + std::to_string(threads));
  AddSetting(&yaml, "output", "csv: " + csv);
  const std::string output = test::RunnerOutput(urdf, yaml, run_name);
  Run run;
  run.csv = ReadTextFile(csv, "the run's CSV");
  const size_t steps = output.find("flexmbd_run: steps:");
  if (steps != std::string::npos) run.steps = output.substr(steps, output.find('\n', steps) - steps);
  return run;
}

void ExpectSameOnTwoThreads(const std::string& urdf, const std::string& yaml, const std::string& name) {
  const Run one = RunOn(urdf, yaml, 1, name), two = RunOn(urdf, yaml, 2, name);
  ASSERT_FALSE(one.steps.empty());
  ASSERT_GT(one.csv.size(), 1000u);
  EXPECT_EQ(one.steps, two.steps);
  EXPECT_TRUE(one.csv == two.csv) << "the CSVs differ (" << one.csv.size() << " and " << two.csv.size() << " bytes)";
}

// Beams, joints, springs, elastic stops and friction in one model (the flexible antenna, 100 steps): its tangent
// assembly (about 200 us) goes to the threads.
TEST(ThreadCount, FlexibleAntennaWithFrictionAndStopsRunsTheSameOnTwoThreads) {
  ExpectSameOnTwoThreads("config/antenna/antenna.urdf", "test/data/yaml/antenna_flexible_friction.yaml",
                         "antenna_flexible_friction");
}

// The published antenna case 0 as shipped (200 s, 694 steps, 4,001 samples at 20 Hz).
TEST(ThreadCount, PublishedAntennaCaseZeroRunsTheSameOnTwoThreads) {
  ExpectSameOnTwoThreads("config/antenna_published/antenna_published.urdf", "config/antenna_published/case0.yaml",
                         "antenna_case0");
}

}  // namespace thread_count_test
}  // namespace flexmbd
