// Models whose bodies travel far beyond their initial extent: Newton's round-off floor follows the coordinates
// (NoiseFloor, docs/theory.md, "Newton iteration"), so such a run steps at its own round-off instead of grinding.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace round_off_test {

TEST(RoundOff, ScrewNutAtTenBillionMetresPerSecondStepsAtItsOwnRoundOff) {
  // Before the floor followed the nut, Newton failed at a residual of 6e-18 relative on every other try: 9,665
  // steps then "step size fell below dt_min". Measured now: 3 steps, and one Newton failure on the first try of
  // dt = 0.01 s, which takes the nut 1e8 m beyond the start whose coordinates set the floor.
  const std::string data = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  const Model model = BuildModel(LoadModelSpec(data + "urdf/screw.urdf", data + "yaml/screw_fast.yaml"));
  Simulation simulation(model);
  OutputSample first, last;
  bool started = false;
  simulation.Run([&](const OutputSample& s) {
    if (!started) first = s;
    started = true;
    last = s;
  });
  EXPECT_LT(simulation.statistics().accepted, 100);
  EXPECT_LE(simulation.statistics().rejected(), 1);
  // Exact: the weight m g along the axis acts on the turn through the pitch p, q'' = -m g p / (J + m p^2) =
  // -9.81e-9 rad/s^2, so q = 10 t - g t^2 / (2 p). Measured 9e-12 relative: Newton stops at tol of the step's
  // acceleration share plus its floor, 100 units in the last place of the nut's 3e7 m; 1e-10 leaves 10x.
  const double t = last.t, exact = 10.0 * t - 0.5 * 9.81 / 1.0e9 * t * t;
  EXPECT_DOUBLE_EQ(t, 0.003);
  EXPECT_NEAR(last.position[0], exact, 1.0e-10 * exact);
  // The scheme conserves energy: what is left is the round-off of a 1.3e17 J total (4e-16 relative measured).
  EXPECT_NEAR(last.total(), first.total(), 1.0e-12 * first.total());
}

}  // namespace round_off_test
}  // namespace flexmbd
