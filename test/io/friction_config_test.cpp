// The `friction` block of a joint (src/io/yaml_friction.cpp, docs/config.md "friction"); values as written.

#include <gtest/gtest.h>

#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace friction_config_test {

const std::string kHingeUrdf = test::HingeUrdf("0 0 1");

TEST(FrictionConfig, CoulombBlockRead) {
  const ModelSpec spec = test::LoadInline(
      kHingeUrdf, "joints: {hinge: {friction: {mu_s: 0.2, mu_k: 0.15, radius: 0.02, preload: 1.25, v0: 8.0e-6}}}");
  const FrictionSpec& f = spec.joints.at(0).effects.at(0).frictions.at(0);
  EXPECT_EQ(f.law, FrictionSpec::Law::kCoulombStick);
  EXPECT_EQ(f.mu_s, 0.2);
  EXPECT_EQ(f.mu_k, 0.15);
  EXPECT_EQ(f.radius, 0.02);
  EXPECT_EQ(f.preload, 1.25);
  EXPECT_EQ(f.v0, 8.0e-6);
}

TEST(FrictionConfig, StaticCoefficientDefaultsToKinetic) {
  const ModelSpec spec = test::LoadInline(kHingeUrdf, "joints: {hinge: {friction: {mu_k: 0.15}}}");
  const FrictionSpec& f = spec.joints.at(0).effects.at(0).frictions.at(0);
  EXPECT_EQ(f.mu_s, 0.15);
  EXPECT_EQ(f.v0, 0.0);  // 0: the automatic threshold
}

TEST(FrictionConfig, RegularisedLawRead) {
  const ModelSpec spec =
      test::LoadInline(kHingeUrdf, "joints: {hinge: {friction: {law: regularised, mu_k: 0.1, v0: 1.0e-3}}}");
  EXPECT_EQ(spec.joints.at(0).effects.at(0).frictions.at(0).law, FrictionSpec::Law::kRegularised);
}

TEST(FrictionConfig, RadiusOnPrismaticJointIsRejected) {
  const std::string slider = test::WorldUrdf({"link"}, R"(
    <joint name="slide" type="prismatic"><parent link="world"/><child link="link"/><axis xyz="1 0 0"/>
      <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>)");
  try {
    test::LoadInline(slider, "joints: {slide: {friction: {mu_k: 0.1, radius: 0.1}}}");
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("joints.slide.friction.radius: applies only to rotations"), std::string::npos)
        << e.what();
  }
}

// Found on the published antenna's case 1 (friction in the driven root hinge): the run failed at t = 0 with a
// singular iteration matrix, the sticking constraint repeating the drive's.
TEST(FrictionConfig, StickingFrictionOnADrivenVariableIsRejectedByBuildModel) {
  const ModelSpec spec = test::LoadInline(kHingeUrdf, "joints: {hinge: {drive: {law: cosine_ramp, value: 0.1}, "
                                                      "friction: {mu_k: 0.15, radius: 0.02}}}");
  EXPECT_CONFIG_ERROR(BuildModel(spec), "joint 'hinge': friction that sticks on a driven variable: sticking would "
                                        "hold the motion the drive prescribes a second time");
}

TEST(FrictionConfig, RegularisedFrictionOnADrivenVariableIsBuilt) {
  const ModelSpec spec = test::LoadInline(kHingeUrdf, "joints: {hinge: {drive: {law: cosine_ramp, value: 0.1}, "
                                                      "friction: {law: regularised, mu_k: 0.15, v0: 1.0e-3}}}");
  EXPECT_NO_THROW(BuildModel(spec));
}

}  // namespace friction_config_test
}  // namespace flexmbd
