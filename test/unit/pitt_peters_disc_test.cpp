// The momentum rows of Pitt and Peters' three-state inflow (docs/theory.md, (A14)) against the published gain
// matrix L of Peters and HaQuang (1988), written with the wake skew angle in the flow's own frame: the rows are its
// inverse, L (rows) = nu; and their slopes against central differences.

#include <gtest/gtest.h>

#include <cmath>

#include "../verification/pitt_peters_gain.hpp"
#include "flexmbd/aero/pitt_peters_disc.hpp"

namespace flexmbd {
namespace pitt_peters_disc_test {

constexpr double kRhoArea = 1.225 * M_PI * 25.0;  // rho pi R^2 of a 5 m disc [kg/m]

struct Case {
  double climb;
  Eigen::Vector2d in_plane;
  Eigen::Vector3d nu;
};
// Hover, axial climb, forward flight at a skew of 60 and 85 deg, and a stream across the disc's axes.
const Case kCases[] = {{0.0, {0.0, 0.0}, {6.0, 0.4, -0.3}},
                       {3.0, {0.0, 0.0}, {4.2, -0.2, 0.5}},
                       {0.0, {10.0, 0.0}, {6.0, 2.0, 1.0}},
                       {1.0, {-20.0, 40.0}, {3.0, 0.7, -1.2}},
                       {-1.0, {6.0, -3.0}, {5.0, 1.5, 2.5}}};

// The rows and L are both exact; their product returns nu to round-off of the ~1e3 N rows (1e-13 relative) times
// L's condition (below 1e2 here): 1e-10 m/s leaves room.
constexpr double kInverseTolerance = 1.0e-10;

TEST(PittPetersDisc, RowsInvertThePublishedGainMatrix) {
  for (const Case& c : kCases) {
    const DiscMomentum m = PittPetersMomentum(c.climb, c.in_plane, c.nu, kRhoArea);
    EXPECT_TRUE(test::PublishedPittPetersInflow(c.climb, c.in_plane, c.nu[0], m.value, kRhoArea)
                    .isApprox(c.nu, kInverseTolerance))
        << "climb " << c.climb << " w " << c.in_plane.transpose();
  }
}

// Central differences with steps of 1e-6 m/s: truncation (1e-6)^2 times the third derivative (rows over nu^2, ~1e2
// N s^3/m^3) and round-off 1e-16 * 1e3 N / 1e-6; 1e-6 of the slope's largest entry (~1e2 N s/m) bounds both.
constexpr double kStep = 1.0e-6, kSlopeTolerance = 1.0e-6;

TEST(PittPetersDisc, SlopeMatchesDifferences) {
  for (const Case& c : kCases) {
    const DiscMomentum m = PittPetersMomentum(c.climb, c.in_plane, c.nu, kRhoArea);
    for (int j = 0; j < 3; ++j) {
      const Eigen::Vector3d step = kStep * Eigen::Vector3d::Unit(j);
      const Eigen::Vector3d difference = (PittPetersMomentum(c.climb, c.in_plane, c.nu + step, kRhoArea).value -
                                          PittPetersMomentum(c.climb, c.in_plane, c.nu - step, kRhoArea).value) /
                                         (2.0 * kStep);
      EXPECT_LT((difference - m.slope.col(j)).norm(), kSlopeTolerance * m.slope.cwiseAbs().maxCoeff())
          << "column " << j << " climb " << c.climb;
    }
  }
}

// At rest (no stream, no inflow) the rows vanish with zero slope, as (A13)'s do: the apparent mass alone moves nu.
TEST(PittPetersDisc, RestHasNoRows) {
  const DiscMomentum m = PittPetersMomentum(0.0, Eigen::Vector2d::Zero(), Eigen::Vector3d::Zero(), kRhoArea);
  EXPECT_EQ(m.value, Eigen::Vector3d::Zero());
  EXPECT_EQ(m.slope, Eigen::Matrix3d::Zero());
}

}  // namespace pitt_peters_disc_test
}  // namespace flexmbd
