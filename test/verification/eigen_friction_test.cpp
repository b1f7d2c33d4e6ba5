// Eigen-analysis leaves friction out (docs/theory.md, "Friction"), run the user's way (flexmbd_run on YAML): a wheel
// on a frictional axle (test/data/urdf/wheel.urdf, its centre of mass on the axle) turns freely, one rigid-body mode.
// The analysis once took the regularised law's slope in the slip rate for a stiffness, mu_k N rho / v0 (490.5 N m/rad,
// a mode at 11.15 Hz), and held a sticking joint by its sticking row (no degree of freedom left).

#include <gtest/gtest.h>

#include <string>

#include "runner_output.hpp"

namespace flexmbd {
namespace eigen_friction_test {

TEST(EigenFriction, FrictionalAxleLeavesTheWheelARigidBodyMode) {
  for (const std::string friction : {"{mu_k: 0.1, law: regularised, v0: 0.01}", "{mu_k: 0.1, mu_s: 0.2}"}) {
    const std::string out = test::RunnerOutput(
        "test/data/urdf/wheel.urdf",
        "joints: {axle: {friction: " + friction + "}}\nsolver: {analysis: eigen}\n", "eigen_friction");
    EXPECT_NE(out.find("1 degrees of freedom, 1 rigid-body modes"), std::string::npos) << friction << "\n" << out;
    EXPECT_EQ(test::ModeRow(out, 1).remark, "rigid body") << friction << "\n" << out;
  }
}

}  // namespace eigen_friction_test
}  // namespace flexmbd
