// The runner's cycle report (output.cycle_from, docs/config.md) on a variable that does not oscillate.

#include <gtest/gtest.h>

#include <string>

#include "runner_output.hpp"

namespace flexmbd {
namespace cycle_report_test {

TEST(CycleReport, SpinningHubRunsOneWayAndHasNoCycle) {
  // test/data/yaml/spinning_blade.yaml: a free hub spun at 10 rad/s with an undamped blade, from 1 s to 2 s. Its
  // angle grows by about 10 rad per s; a mean, an amplitude and a frequency of it were reported as a cycle. The
  // mean rate is the spin less what the blade's stretch and its axial vibration take from the free hub (measured
  // 9.99819 rad/s): within 1e-3 of 10 rad/s relative, 1e-2 rad/s.
  std::string yaml = test::SourceText("test/data/yaml/spinning_blade.yaml");
  const std::string output = "output: {rate_hz: 100}";
  ASSERT_NE(yaml.find(output), std::string::npos);
  yaml.replace(yaml.find(output), output.size(), "output: {rate_hz: 100, cycle_from: 1.0}");
  const std::string out = test::RunnerOutput("test/data/urdf/spinning_hub.urdf", yaml, "spinning_hub_cycle");
  const std::string line = "flexmbd_run: cycle of spin over [1, 2] s: none, it runs one way from ";
  const size_t at = out.find(line);
  ASSERT_NE(at, std::string::npos) << out;
  const size_t rate = out.find("(mean rate ", at);
  ASSERT_NE(rate, std::string::npos) << out;
  EXPECT_NEAR(std::stod(out.substr(rate + 11)), 10.0, 1.0e-2) << out;
  EXPECT_NE(out.find(" per s) without turning back\n", rate), std::string::npos) << out;
  EXPECT_EQ(out.find("amplitude"), std::string::npos) << out;
}

}  // namespace cycle_report_test
}  // namespace flexmbd
