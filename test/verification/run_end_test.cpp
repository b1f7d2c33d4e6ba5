// A run's steps before its last ones do not depend on where it ends (docs/theory.md, "Last steps" and (T12b)), run
// the user's way: flexmbd_run on the published antenna's case 0 (config/antenna_published), whose beams have
// structural damping, to two end times.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace run_end_test {

// Every step of case 0 to t_end (the YAML's 200 s replaced).
test::CsvTable EveryStep(double t_end) {
  std::string yaml = test::SourceText("config/antenna_published/case0.yaml");
  const std::string given_end = "t_end: 200.0", given_output = "output:";
  yaml.replace(yaml.find(given_end), given_end.size(), "t_end: " + std::to_string(t_end));
  const std::string name = "antenna_case0_to_" + std::to_string(static_cast<int>(t_end));
  const std::string csv = testing::TempDir() + name + ".csv";
  yaml = yaml.substr(0, yaml.find(given_output)) + "output: {rate_hz: 0, csv: " + csv + "}\n";
  test::RunnerOutput("config/antenna_published/antenna_published.urdf", yaml, name);
  return test::ReadCsv(csv);
}

TEST(RunEnd, StepsOfADampedBeamModelBeforeTheLastOnesDoNotDependOnTheEndTime) {
  // The damped deformation's error entry (T12b) was discounted by the time left to t_end, so every step, from the
  // first, depended on it: run to 2 s and to 4 s, the hinges differed by 1.4e-6 rad from the sample at 0.1 s on
  // (2.7e-5 rad between 10 s and 200 s; measured before: the steps differ from the fifth, at 0.0649 s). Now its
  // horizon is the time the motion takes to move by the model's size at its peak speed, or the time run if longer,
  // and only the last steps (at most three, the window of "Last steps") differ: every step before them is the same,
  // bit for bit.
  const test::CsvTable shorter = EveryStep(2.0), longer = EveryStep(4.0);
  ASSERT_GT(shorter.rows.size(), 10u);
  ASSERT_GT(longer.rows.size(), shorter.rows.size());
  constexpr size_t kLastSteps = 3;
  for (size_t k = 0; k + kLastSteps < shorter.rows.size(); ++k) {
    ASSERT_EQ(shorter.rows[k], longer.rows[k]) << "step " << k << " at t = " << shorter.rows[k][0];
  }
}

}  // namespace run_end_test
}  // namespace flexmbd
