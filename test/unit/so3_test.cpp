// SO(3) tools (include/flexmbd/math/so3.hpp) against closed forms and identities.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/LU>

#include "flexmbd/math/so3.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace so3_test {

// Angles spanning the series branches of the implementation (tiny angles), the range where closed forms such
// as (1 - cos x)/x^2 would cancel (1e-4 .. 1e-2), both sides of the series switches seen so far (1e-4, 0.5), and
// large angles up to pi.
const std::vector<double> kSweepAngles = {0.0,     1.0e-12, 1.0e-9, 1.0e-6, 9.9e-5, 1.0e-4,
                                          1.01e-4, 3.0e-4,  1.0e-3, 1.0e-2, 0.1,    0.49,
                                          0.5,     0.51,    1.0,    2.0,    3.0,    M_PI - 1e-6};

// Reference ratios in long double (64-bit mantissa): (1 - cos x)/x^2 by the half-angle form 2 sin^2(x/2)/x^2,
// which has no cancellation, and (x - sin x)/x^3 by its series where the difference would cancel.
long double OneMinusCosOverSquareReference(long double x) {
  if (x == 0.0L) return 0.5L;
  const long double s = std::sin(0.5L * x) / (0.5L * x);
  return 0.5L * s * s;
}

long double XMinusSinOverCubeReference(long double x) {
  const long double x2 = x * x;
  if (std::abs(x) < 1.0e-2L) {
    // Truncation after the x^8 term: x^10 / 39916800 < 3e-28 here.
    return 1.0L / 6 - x2 / 120 + x2 * x2 / 5040 - x2 * x2 * x2 / 362880 + x2 * x2 * x2 * x2 / 39916800;
  }
  return (x - std::sin(x)) / (x2 * x);
}

TEST(So3, SkewIsCrossProductAndAxialInvertsIt) {
  // Reference: definition Skew(a) b = a x b and Axial(Skew(a)) = a.
  // Each entry is one product or difference: exact to one rounding.
  constexpr double kRoundOff = 1.0e-15;
  test::Random random(1);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 a = random.Vector(2.0), b = random.Vector(2.0);
    EXPECT_LT((Skew(a) * b - a.cross(b)).norm(), kRoundOff);
    EXPECT_LT((Axial(Skew(a)) - a).norm(), kRoundOff);
    EXPECT_LT((Skew(a) + Skew(a).transpose()).norm(), kRoundOff);
  }
}

TEST(So3, ExpIsOrthonormalWithUnitDeterminant) {
  // Reference: Exp(theta) in SO(3): R^T R = I, det R = 1, and Exp(theta) theta = theta (axis fixed).
  // Rodrigues sums three O(1) terms: a few ulp per entry.
  constexpr double kOrthonormality = 1.0e-14;
  test::Random random(2);
  for (double angle : kSweepAngles) {
    for (double scale : {1.0, 10.0}) {
      const Vec3 theta = scale * angle * random.UnitVector();
      const Mat3 R = Exp(theta);
      EXPECT_LT((R.transpose() * R - Mat3::Identity()).norm(), kOrthonormality) << "theta " << theta.transpose();
      EXPECT_NEAR(R.determinant(), 1.0, kOrthonormality) << "theta " << theta.transpose();
      EXPECT_LT((R * theta - theta).norm(), kOrthonormality * (1.0 + theta.norm()));
    }
  }
}

TEST(So3, ExpMatchesRodriguesAboutCoordinateAxis) {
  // Reference: rotation about z by a: [[cos a, -sin a, 0], [sin a, cos a, 0], [0, 0, 1]].
  // One rounding per trigonometric factor: a few ulp.
  constexpr double kRoundOff = 1.0e-15;
  for (double a : {-2.5, -0.3, 1.0e-5, 0.7, 3.0}) {
    Mat3 expected;
    expected << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    EXPECT_LT((Exp(a * Vec3::UnitZ()) - expected).norm(), kRoundOff) << "a " << a;
  }
}

TEST(So3, LogInvertsExpForRandomVectorsInsidePi) {
  // Reference: Log(Exp(theta)) = theta for |theta| < pi.
  // Below a quarter turn Log takes the axis from the skew part, beyond it through a quaternion; both are well
  // conditioned there (the skew part is sin(angle) >= 1/sqrt(2) of the axis at the switch): error a few ulp of
  // |theta| <= pi. The uniform angles put about half the trials on each side.
  constexpr double kRoundTrip = 1.0e-14;
  test::Random random(3);
  for (int trial = 0; trial < 500; ++trial) {
    const Vec3 theta = random.Uniform(0.0, M_PI - 1.0e-3) * random.UnitVector();
    EXPECT_LT((Log(Exp(theta)) - theta).norm(), kRoundTrip) << "theta " << theta.transpose();
  }
}

TEST(So3, LogInvertsExpNearZero) {
  // Reference: Log(Exp(theta)) = theta; relative accuracy must survive tiny angles (no absolute floor).
  // The skew part of Exp is theta Sinc, exact to a few ulp relative to |theta|.
  constexpr double kRelativeRoundTrip = 1.0e-14;
  test::Random random(4);
  for (double angle : {1.0e-15, 1.0e-12, 1.0e-9, 1.0e-6, 9.9e-5, 1.01e-4, 1.0e-3}) {
    const Vec3 theta = angle * random.UnitVector();
    EXPECT_LT((Log(Exp(theta)) - theta).norm(), kRelativeRoundTrip * angle) << "angle " << angle;
  }
  EXPECT_EQ(Log(Mat3::Identity()).norm(), 0.0);
}

TEST(So3, LogInvertsExpNearPi) {
  // Reference: Log(Exp(theta)) = theta for |theta| just below pi (the axis sign is still determined).
  // At pi - delta the quaternion scalar part is ~delta/2 and carries ~1e-16 absolute error, so the axis and
  // angle are exact to a few ulp; 1e-13 leaves a margin for the matrix-to-quaternion branch.
  constexpr double kRoundTrip = 1.0e-13;
  test::Random random(5);
  for (double delta : {1.0e-3, 1.0e-6, 1.0e-9}) {
    for (int trial = 0; trial < 20; ++trial) {
      const Vec3 theta = (M_PI - delta) * random.UnitVector();
      EXPECT_LT((Log(Exp(theta)) - theta).norm(), kRoundTrip) << "delta " << delta;
    }
  }
}

TEST(So3, LogAtPiReturnsAnAngleOfPi) {
  // Reference: at exactly pi, theta and -theta give the same rotation; Log returns one of them.
  // Exp at pi is exact to a few ulp; the recovered axis is then exact to ~sqrt(ulp) at worst (the quaternion
  // vector part is found from a square root of diagonal sums), so compare rotations, not vectors.
  constexpr double kRotationMatch = 1.0e-12;
  test::Random random(6);
  for (int trial = 0; trial < 20; ++trial) {
    const Mat3 R = Exp(M_PI * random.UnitVector());
    const Vec3 log = Log(R);
    EXPECT_NEAR(log.norm(), M_PI, kRotationMatch);
    EXPECT_LT((Exp(log) - R).norm(), kRotationMatch);
  }
}

TEST(So3, RightJacobianMatchesFiniteDifferenceOfExp) {
  // Reference: d Exp(theta) = Exp(theta) Skew(T(theta) d theta), so column j of T is
  // Axial(Exp(theta)^T (Exp(theta + eps e_j) - Exp(theta - eps e_j))) / (2 eps).
  // Central difference with eps = 1e-5: truncation eps^2 |d3 Exp| ~ 1e-10, round-off ulp/eps ~ 1e-11.
  constexpr double kStep = 1.0e-5;
  constexpr double kFiniteDifference = 1.0e-9;
  test::Random random(7);
  for (double angle : kSweepAngles) {
    const Vec3 theta = angle * random.UnitVector();
    const Mat3 T = RightJacobian(theta);
    for (int j = 0; j < 3; ++j) {
      const Vec3 e = kStep * Vec3::Unit(j);
      const Vec3 column = Axial(Exp(theta).transpose() * (Exp(theta + e) - Exp(theta - e))) / (2.0 * kStep);
      EXPECT_LT((column - T.col(j)).norm(), kFiniteDifference) << "angle " << angle << " column " << j;
    }
  }
}

TEST(So3, RightJacobianMatchesClosedForm) {
  // Reference: T = I - (1 - cos x)/x^2 K + (x - sin x)/x^3 K^2, x = |theta|, K = Skew(theta), with the
  // ratios evaluated in long double without cancellation.
  // A correctly evaluated double T is exact to a few ulp of its O(1) entries.
  constexpr double kClosedForm = 2.0e-15;
  test::Random random(8);
  for (double angle : kSweepAngles) {
    const Vec3 theta = angle * random.UnitVector();
    const Mat3 K = Skew(theta);
    const long double x = angle;
    const Mat3 expected = Mat3::Identity() - static_cast<double>(OneMinusCosOverSquareReference(x)) * K +
                          static_cast<double>(XMinusSinOverCubeReference(x)) * K * K;
    EXPECT_LT((RightJacobian(theta) - expected).cwiseAbs().maxCoeff(), kClosedForm) << "angle " << angle;
  }
}

TEST(So3, IncrementMapsAreExpSecantOperatorAndRightJacobian) {
  // Reference: the three functions called one by one. The same ratios go through the same products: equal to
  // round-off of entries of size up to |theta|^2 (two units in the last place).
  test::Random random(12);
  for (double angle : kSweepAngles) {
    const Vec3 theta = angle * random.UnitVector();
    const IncrementMaps maps = IncrementMapsOf(theta);
    const double round_off = 2.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, angle * angle);
    EXPECT_LT((maps.exp - Exp(theta)).cwiseAbs().maxCoeff(), round_off) << "angle " << angle;
    EXPECT_LT((maps.secant - SecantOperator(theta)).cwiseAbs().maxCoeff(), round_off) << "angle " << angle;
    EXPECT_LT((maps.right_jacobian - RightJacobian(theta)).cwiseAbs().maxCoeff(), round_off) << "angle " << angle;
  }
}

TEST(So3, SecantOperatorSatisfiesExpMinusIdentity) {
  // Reference: identity Exp(theta) - I = Skew(theta) S(theta), exact for finite theta, for tiny angles (1e-9,
  // where series are used) and finite ones.
  // Both sides are O(|theta|) sums of a few rounded products: 1e-14 absolute.
  constexpr double kIdentity = 1.0e-14;
  test::Random random(9);
  for (double angle : kSweepAngles) {
    for (int trial = 0; trial < 5; ++trial) {
      const Vec3 theta = angle * random.UnitVector();
      EXPECT_LT((Exp(theta) - Mat3::Identity() - Skew(theta) * SecantOperator(theta)).cwiseAbs().maxCoeff(), kIdentity)
          << "angle " << angle;
    }
  }
}

TEST(So3, SecantOperatorMapsBodyVectorChange) {
  // Reference: the documented consequence (Exp(theta) - I) d = -Skew(S(theta) d) theta for any d.
  // Products of O(1) factors: a few ulp.
  constexpr double kIdentity = 1.0e-14;
  test::Random random(10);
  for (double angle : kSweepAngles) {
    const Vec3 theta = angle * random.UnitVector();
    const Vec3 d = random.Vector(1.0);
    EXPECT_LT(((Exp(theta) - Mat3::Identity()) * d + Skew(SecantOperator(theta) * d) * theta).norm(), kIdentity)
        << "angle " << angle;
  }
}

TEST(So3, SecantOperatorMatchesClosedForm) {
  // Reference: S = Sinc(x) I + (1 - cos x)/x^2 Skew(theta), x = |theta|, the ratio evaluated in long double by
  // the cancellation-free half-angle form.
  // A correctly evaluated double S is exact to a few ulp of its O(1) entries.
  constexpr double kClosedForm = 2.0e-15;
  test::Random random(11);
  for (double angle : kSweepAngles) {
    const Vec3 theta = angle * random.UnitVector();
    const long double x = angle;
    const double sinc = x == 0.0L ? 1.0 : static_cast<double>(std::sin(x) / x);
    const Mat3 expected =
        sinc * Mat3::Identity() + static_cast<double>(OneMinusCosOverSquareReference(x)) * Skew(theta);
    EXPECT_LT((SecantOperator(theta) - expected).cwiseAbs().maxCoeff(), kClosedForm) << "angle " << angle;
  }
}

TEST(So3, AxisAngleRotatesAboutTheAxis) {
  // Reference: Rodrigues for a unit axis a: R v = cos q v + sin q (a x v) + (1 - cos q)(a . v) a;
  // the axis is invariant.
  // A few rounded products of O(1) terms.
  constexpr double kRoundOff = 1.0e-14;
  test::Random random(12);
  for (int trial = 0; trial < 20; ++trial) {
    const Vec3 a = random.UnitVector();
    const double q = random.Uniform(-2.0 * M_PI, 2.0 * M_PI);
    const Vec3 v = random.Vector(1.0);
    const Vec3 expected = std::cos(q) * v + std::sin(q) * a.cross(v) + (1.0 - std::cos(q)) * a.dot(v) * a;
    const Mat3 R = AxisAngle(a, q);
    EXPECT_LT((R * v - expected).norm(), kRoundOff);
    EXPECT_LT((R * a - a).norm(), kRoundOff);
    EXPECT_LT((R - Exp(q * a)).norm(), kRoundOff);
  }
}

TEST(So3, SincMatchesSinOverX) {
  // Reference: sin(x)/x, and its limit 1 at x = 0; the series branch (|x| < 1e-4) must join it smoothly.
  // The series truncation x^4/120 < 1e-18 near the switch, plus one rounding.
  constexpr double kRoundOff = 2.0e-16;
  EXPECT_EQ(Sinc(0.0), 1.0);
  for (double x : {1.0e-9, -5.0e-5, 9.99e-5, 1.0e-4, 1.001e-4, 0.3, -2.0, 3.0}) {
    EXPECT_NEAR(Sinc(x), std::sin(x) / x, kRoundOff) << "x " << x;
  }
}

}  // namespace so3_test
}  // namespace flexmbd
