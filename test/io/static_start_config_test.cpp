// A static start (solver.static_first, solver.eigen.static_first) begins at rest: a non-zero initial velocity given
// with it is an error naming the file and the field, instead of being dropped (test/data/yaml/pend_static_vel.yaml
// once started its pendulum at rest, its 2 rad/s gone).

#include <gtest/gtest.h>

#include "io_test_util.hpp"

namespace flexmbd {
namespace static_start_config_test {

TEST(StaticStartConfig, InitialVelocityWithStaticFirstIsAnErrorAtTheVelocity) {
  EXPECT_CONFIG_ERROR(LoadModelSpec(test::DataPath("urdf/pend_rev.urdf"), test::DataPath("yaml/pend_static_vel.yaml")),
                      "pend_static_vel.yaml: joints.pivot.initial.velocity: 2.0 with solver.static_first: true, which "
                      "starts from the static equilibrium at rest");
}

TEST(StaticStartConfig, InitialVelocityWithAStaticEigenAnalysisIsAnError) {
  EXPECT_CONFIG_ERROR(test::LoadDataUrdf("pend_rev.urdf",
                                         "joints: {pivot: {initial: {velocity_deg: 30.0}}}\n"
                                         "solver: {analysis: eigen, eigen: {static_first: true}}",
                                         "eigen.yaml"),
                      "eigen.yaml: joints.pivot.initial.velocity_deg: 30.0 with solver.eigen.static_first: true");
}

TEST(StaticStartConfig, TheSecondVariableOfAJointIsNamedByItsEntry) {
  EXPECT_CONFIG_ERROR(test::LoadDataUrdf("planar.urdf",
                                         "joints: {plane: {variables: [{}, {}, {initial: {velocity: -0.5}}]}}\n"
                                         "solver: {static_first: true}",
                                         "planar.yaml"),
                      "planar.yaml: joints.plane.variables[2].initial.velocity: -0.5 with solver.static_first");
}

TEST(StaticStartConfig, ZeroVelocitiesDrivesAndRunsWithoutAStaticStartAreAccepted) {
  for (const char* yaml : {"joints: {pivot: {initial: {position: 0.5, velocity: 0.0}}}\nsolver: {static_first: true}",
                           "joints: {pivot: {drive: {law: linear_ramp, value: 1.0, duration: 1.0}}}\n"
                           "solver: {static_first: true}",
                           "joints: {pivot: {initial: {velocity: 2.0}}}\nsolver: {static_first: false}",
                           "joints: {pivot: {initial: {velocity: 2.0}}}\nsolver: {analysis: eigen}"}) {
    EXPECT_EQ(test::ConfigErrorOf([&]() { test::LoadDataUrdf("pend_rev.urdf", yaml, "ok.yaml"); }),
              "(no ConfigError thrown)")
        << yaml;
  }
}

}  // namespace static_start_config_test
}  // namespace flexmbd
