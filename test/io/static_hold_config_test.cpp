// `initial.static_hold` (docs/config.md, "joints"): read from the YAML, and refused by BuildModel where no static
// analysis would hold the variable or a drive holds it already.

#include <gtest/gtest.h>

#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace static_hold_config_test {

const std::string kHingeUrdf = test::HingeUrdf("0 1 0");

TEST(StaticHoldConfig, ReadWithTheInitialPosition) {
  const ModelSpec spec = test::LoadInline(
      kHingeUrdf, "joints: {hinge: {initial: {position_deg: 9.7, static_hold: true}}}\nsolver: {static_first: true}");
  EXPECT_TRUE(spec.joints.at(0).effects.at(0).static_hold);
  EXPECT_DOUBLE_EQ(spec.joints.at(0).initial_position.at(0), 9.7 * M_PI / 180.0);
  EXPECT_NO_THROW(BuildModel(spec));
}

TEST(StaticHoldConfig, WithoutAStaticAnalysisIsRejectedByBuildModel) {
  const ModelSpec spec = test::LoadInline(kHingeUrdf, "joints: {hinge: {initial: {static_hold: true}}}");
  EXPECT_CONFIG_ERROR(BuildModel(spec), "joint 'hinge': initial.static_hold holds the variable in a static analysis, "
                                        "and this run has none; expected solver.static_first: true");
}

// Once told "this run has none; expected solver.static_first: true" with eigen.static_first set (explore23
// bad/eigen/static_hold_eigen.yaml), solver.static_first being a dynamic run's.
TEST(StaticHoldConfig, InAnEigenAnalysisIsRejectedForWhatItIs) {
  const ModelSpec spec = test::LoadInline(kHingeUrdf, "joints: {hinge: {initial: {static_hold: true}}}\n"
                                                      "solver: {analysis: eigen, eigen: {static_first: true}}");
  EXPECT_CONFIG_ERROR(BuildModel(spec), "joint 'hinge': initial.static_hold in an eigen-analysis, which linearises "
                                        "about the free system (with solver.eigen.static_first: its equilibrium "
                                        "without holds); expected no static_hold here");
}

TEST(StaticHoldConfig, OnADrivenVariableIsRejectedByBuildModel) {
  const ModelSpec spec = test::LoadInline(
      kHingeUrdf, "joints: {hinge: {drive: {law: constant, value: 0.1}, initial: {static_hold: true}}}\n"
                  "solver: {static_first: true}");
  EXPECT_CONFIG_ERROR(BuildModel(spec), "joint 'hinge': initial.static_hold on a driven variable");
}

TEST(StaticHoldConfig, NotABoolIsRejected) {
  EXPECT_CONFIG_ERROR(test::LoadInline(kHingeUrdf, "joints: {hinge: {initial: {static_hold: 3}}}"),
                      "joints.hinge.initial.static_hold");
}

}  // namespace static_hold_config_test
}  // namespace flexmbd
