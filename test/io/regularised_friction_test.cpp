// The regularised friction law never sticks: a static coefficient given with it is an error (it was accepted and
// ignored, test/data/yaml/regularised_with_mu_s.yaml), and the runner reports the v0 the user gave as that law's
// regularisation speed (it printed a "sticking threshold" of 0.01 m/s for a given 0.1, incline_drive_reg.yaml).

#include <gtest/gtest.h>

#include <string>

#include "../verification/runner_output.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace regularised_friction_test {

TEST(RegularisedFriction, StaticCoefficientIsAnErrorAtMuS) {
  EXPECT_CONFIG_ERROR(
      LoadModelSpec(test::DataPath("urdf/wheel.urdf"), test::DataPath("yaml/regularised_with_mu_s.yaml")),
      "regularised_with_mu_s.yaml: joints.axle.friction.mu_s: the regularised law mu_k rho N (1 - exp(-|v|/v0)) "
      "never sticks and has no static coefficient; expected no mu_s with law: regularised");
}

TEST(RegularisedFriction, RunnerPrintsTheGivenRegularisationSpeed) {
  const std::string out = test::RunnerOutput("test/data/urdf/incline.urdf",
                                             test::ReadDataText("yaml/incline_drive_reg.yaml"), "incline_drive_reg");
  EXPECT_NE(out.find("friction slide: regularised, v0 = 0.1 m/s (never sticks), largest slip speed "),
            std::string::npos)
      << out;
  EXPECT_EQ(out.find("sticking"), std::string::npos) << out;
}

}  // namespace regularised_friction_test
}  // namespace flexmbd
