// A model with nothing to move (no body, no beam) is a ConfigError at load, never a crash in the solver.
// Reference: docs/config.md "URDF mapping".

#include <gtest/gtest.h>

#include "flexmbd/model/model.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace nothing_to_move_test {
using test::LoadInline;

TEST(NothingToMove, WorldAloneIsRejected) {
  EXPECT_CONFIG_ERROR(LoadInline("<robot name=\"r\"><link name=\"world\"/></robot>", ""),
                      "test.urdf: nothing can move: root link 'world' is the ground and there is no other link; "
                      "expected at least one link with <inertial>");
}

TEST(NothingToMove, OnlyFixedFramesAreRejected) {
  const std::string urdf = R"(<robot name="r"><link name="base"/><link name="camera"/>
    <joint name="mount" type="fixed"><parent link="base"/><child link="camera"/></joint></robot>)";
  EXPECT_CONFIG_ERROR(LoadInline(urdf, ""),
                      "test.urdf: nothing can move: root link 'base' is the ground and every other link is fixed "
                      "to it as a frame (no <inertial>)");
}

TEST(NothingToMove, BodyFixedToTheGroundStillLoads) {
  const std::string urdf = test::WorldUrdf({"block"}, R"(
    <joint name="weld" type="fixed"><parent link="world"/><child link="block"/></joint>)");
  EXPECT_EQ(BuildModel(LoadInline(urdf, "")).bodies().size(), 1u);
}

TEST(NothingToMove, SpecWithoutBodiesOrBeamsIsRejectedByBuildModel) {
  ModelSpec spec;
  spec.source = "hand.urdf";
  EXPECT_CONFIG_ERROR(BuildModel(spec), "hand.urdf: nothing can move: the model has no body and no beam");
}

}  // namespace nothing_to_move_test
}  // namespace flexmbd
