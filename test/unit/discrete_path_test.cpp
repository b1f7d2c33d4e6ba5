// Exact discrete gradients (include/flexmbd/math/discrete_path.hpp): for every path,
//   value_f - value_i = sum_k dg[k] xi_k   exactly (the identity the energy-consistent joints rest on), and
//   df[k] = d value_f / d xi_k            (checked against central finite differences).
// Local increments of the test step: node a at 0..5 (dx, theta), node b at 6..11, two joint variables at 12, 13.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/math/discrete_path.hpp"
#include "flexmbd/math/so3.hpp"
#include "unit_test_helpers.hpp"

namespace flexmbd {
namespace discrete_path_test {

constexpr int kNodeA = 0, kNodeB = 6, kVariables = 12, kNumIncrements = 14;

// The identity is exact in exact arithmetic; in double each side is a sum of ~20 rounded O(1..10) products.
constexpr double kExactIdentity = 1.0e-13;
// Central differences with step 1e-6: truncation ~1e-12 * |d3 value|, round-off ~1e-16 * |value| / 1e-6 = 1e-10.
constexpr double kFiniteDifferenceStep = 1.0e-6;
constexpr double kFiniteDifference = 1.0e-8;

// One step of two nodes and two joint variables.
struct TwoNodeStep {
  NodeStep a, b;
  Eigen::VectorXd q_i, q_f;

  // The increments xi in local order.
  Eigen::VectorXd Increments() const {
    Eigen::VectorXd xi(kNumIncrements);
    xi << a.dx, a.theta, b.dx, b.theta, q_f - q_i;
    return xi;
  }
};

// Random start poses and increments; |theta| and |dq| up to `rotation_scale` [rad].
TwoNodeStep RandomStep(test::Random* random, double rotation_scale) {
  TwoNodeStep s;
  auto node = [&]() {
    Vec6 increment;
    increment << random->Vector(0.5), random->Uniform(0.0, rotation_scale) * random->UnitVector();
    return MakeNodeStep(random->Node(2.0, 1.0), increment, AnalysisMode::kDynamic);
  };
  s.a = node();
  s.b = node();
  s.q_i = random->VectorX(2, M_PI);
  s.q_f = s.q_i + random->VectorX(2, rotation_scale);
  return s;
}

template <int Cols>
using PathOf = std::function<DiscretePath<Cols>(const TwoNodeStep&)>;

// Checks value_f - value_i == sum_k dg[k] xi_k over random steps.
template <int Cols>
void ExpectExactDiscreteGradient(const PathOf<Cols>& make, double rotation_scale, unsigned seed) {
  test::Random random(seed);
  for (int trial = 0; trial < 20; ++trial) {
    const TwoNodeStep s = RandomStep(&random, rotation_scale);
    const DiscretePath<Cols> p = make(s);
    const Eigen::VectorXd xi = s.Increments();
    typename DiscretePath<Cols>::Value sum = DiscretePath<Cols>::Value::Zero();
    for (int k = 0; k < kNumIncrements; ++k) sum += p.gradient(k) * xi[k];
    const double scale = 1.0 + test::MaxAbs(p.i) + test::MaxAbs(p.f);
    EXPECT_LT(test::MaxAbs(p.f - p.i - sum), kExactIdentity * scale) << "trial " << trial;
  }
}

// The step with local increment k moved by `d` (node increments through PerturbNodeStep).
TwoNodeStep Perturbed(const TwoNodeStep& s, int k, double d) {
  TwoNodeStep moved = s;
  if (k < kVariables) {
    Vec6 delta = Vec6::Zero();
    delta[k % 6] = d;
    NodeStep& node = k < kNodeB ? moved.a : moved.b;
    node = PerturbNodeStep(node, delta, AnalysisMode::kDynamic);
  } else {
    moved.q_f[k - kVariables] += d;
  }
  return moved;
}

// Checks df[k] against central differences of value_f over random steps.
template <int Cols>
void ExpectDerivativeMatchesFiniteDifference(const PathOf<Cols>& make, double rotation_scale, unsigned seed) {
  test::Random random(seed);
  for (int trial = 0; trial < 5; ++trial) {
    const TwoNodeStep s = RandomStep(&random, rotation_scale);
    const DiscretePath<Cols> p = make(s);
    for (int k = 0; k < kNumIncrements; ++k) {
      const auto plus = make(Perturbed(s, k, kFiniteDifferenceStep)).f;
      const auto minus = make(Perturbed(s, k, -kFiniteDifferenceStep)).f;
      const auto fd = ((plus - minus) / (2.0 * kFiniteDifferenceStep)).eval();
      const double scale = 1.0 + test::MaxAbs(p.f);
      EXPECT_LT(test::MaxAbs(p.derivative(k) - fd), kFiniteDifference * scale)
          << "trial " << trial << " increment " << k;
    }
  }
}

// The paths under test.
MatrixPath RotationA(const TwoNodeStep& s) { return NodeRotationPath(s.a, kNodeA + 3); }
MatrixPath RotationB(const TwoNodeStep& s) { return NodeRotationPath(s.b, kNodeB + 3); }
VectorPath PositionA(const TwoNodeStep& s) { return NodePositionPath(s.a, kNodeA); }
VectorPath PositionB(const TwoNodeStep& s) { return NodePositionPath(s.b, kNodeB); }

Vec3 FixedAxis() { return Vec3(0.3, -0.5, 0.8).normalized(); }

MatrixPath AxisRotation(const TwoNodeStep& s) {
  return AxisRotationPath(FixedAxis(), s.q_i[1], s.q_f[1], kVariables + 1);
}

VectorPath Linear(const TwoNodeStep& s) {
  return LinearPath({Vec3(1.0, 2.0, -0.5), Vec3(-0.3, 0.1, 0.7)}, s.q_i, s.q_f, kVariables);
}

// Transpose(R_a) R_b d: a body-b vector seen from body a.
VectorPath RelativeVector(const TwoNodeStep& s) {
  return Transpose(RotationA(s)) * (RotationB(s) * ConstantPath<1>(Vec3(0.4, -1.2, 0.3)));
}

// The rotation constraint of a two-axis joint: Transpose(Rel(q)) R_aJ^T R_a^T R_b R_bJ.
MatrixPath JointRotationChain(const TwoNodeStep& s) {
  const MatrixPath rel = AxisRotationPath(Vec3::UnitZ(), s.q_i[0], s.q_f[0], kVariables) *
                         AxisRotationPath(FixedAxis(), s.q_i[1], s.q_f[1], kVariables + 1);
  const MatrixPath R_aJ = ConstantPath<3>(Exp(Vec3(0.2, -0.4, 0.9)));
  const MatrixPath R_bJ = ConstantPath<3>(Exp(Vec3(-1.1, 0.3, 0.5)));
  return Transpose(rel) * (Transpose(R_aJ) * (Transpose(RotationA(s)) * (RotationB(s) * R_bJ)));
}

// The position constraint of a joint: x_b + R_b c_b - x_a - R_a (c_a + Rel(q) t(q)).
VectorPath JointPositionChain(const TwoNodeStep& s) {
  const VectorPath c_b = ConstantPath<1>(Vec3(0.1, 0.2, -0.3));
  const VectorPath c_a = ConstantPath<1>(Vec3(-0.5, 0.4, 0.2));
  return PositionB(s) + RotationB(s) * c_b - PositionA(s) - RotationA(s) * (c_a + AxisRotation(s) * Linear(s));
}

// `p` without its derivatives: what is built from it keeps only values and discrete gradients.
template <int Cols>
DiscretePath<Cols> WithoutDerivative(DiscretePath<Cols> p) {
  p.has_derivative = false;
  return p;
}

// JointPositionChain with every varying factor built without derivatives (the joints' residual-only path).
VectorPath JointPositionChainWithoutDerivative(const TwoNodeStep& s) {
  const VectorPath c_b = ConstantPath<1>(Vec3(0.1, 0.2, -0.3));
  const VectorPath c_a = ConstantPath<1>(Vec3(-0.5, 0.4, 0.2));
  return WithoutDerivative(PositionB(s)) + WithoutDerivative(RotationB(s)) * c_b - WithoutDerivative(PositionA(s)) -
         WithoutDerivative(RotationA(s)) *
             (c_a + WithoutDerivative(AxisRotation(s)) * WithoutDerivative(Linear(s)));
}

// Transpose(R_a) R_b d with only R_a built without derivatives.
VectorPath RelativeVectorOneFactorWithoutDerivative(const TwoNodeStep& s) {
  return Transpose(WithoutDerivative(RotationA(s))) * (RotationB(s) * ConstantPath<1>(Vec3(0.4, -1.2, 0.3)));
}

TEST(DiscretePath, PathWithoutDerivativeKeepsValuesAndGradientsToTheBit) {
  // Reference: dropping df changes which products are formed, not how i, f and dg are computed, so they
  // agree exactly with the full path's; what is built from a factor without derivatives has none.
  test::Random random(121);
  for (int trial = 0; trial < 5; ++trial) {
    const TwoNodeStep s = RandomStep(&random, 2.0);
    for (const auto& [full, reduced] :
         {std::pair{JointPositionChain(s), JointPositionChainWithoutDerivative(s)},
          std::pair{RelativeVector(s), RelativeVectorOneFactorWithoutDerivative(s)}}) {
      EXPECT_TRUE(full.has_derivative);
      EXPECT_FALSE(reduced.has_derivative);
      EXPECT_EQ(reduced.active, full.active);
      EXPECT_EQ(reduced.i, full.i);
      EXPECT_EQ(reduced.f, full.f);
      for (int k = 0; k < kNumIncrements; ++k) EXPECT_EQ(reduced.gradient(k), full.gradient(k)) << "increment " << k;
    }
  }
}

TEST(DiscretePath, TransposeTimesIsTheProductWithTheTranspose) {
  // Reference: Transpose(a) * b formed explicitly. The same products of the same numbers: equal to the bit.
  test::Random random(122);
  for (int trial = 0; trial < 5; ++trial) {
    const TwoNodeStep s = RandomStep(&random, 2.0);
    const VectorPath b = RotationB(s) * ConstantPath<1>(Vec3(0.4, -1.2, 0.3));
    const VectorPath expected = Transpose(RotationA(s)) * b, product = TransposeTimes(RotationA(s), b);
    EXPECT_EQ(product.active, expected.active);
    EXPECT_EQ(product.i, expected.i);
    EXPECT_EQ(product.f, expected.f);
    for (int k = 0; k < kNumIncrements; ++k) {
      EXPECT_EQ(product.gradient(k), expected.gradient(k)) << "increment " << k;
      EXPECT_EQ(product.derivative(k), expected.derivative(k)) << "increment " << k;
    }
  }
}

TEST(DiscretePath, ConstantPathHasZeroGradients) {
  // Reference: a constant has value_f = value_i and no dependence on any increment (exact zeros).
  const MatrixPath p = ConstantPath<3>(Exp(Vec3(0.1, 0.2, 0.3)));
  EXPECT_EQ(p.i, p.f);
  EXPECT_EQ(p.active, 0u);
  for (int k = 0; k < kNumIncrements; ++k) {
    EXPECT_TRUE(p.gradient(k).isZero(0.0));
    EXPECT_TRUE(p.derivative(k).isZero(0.0));
  }
}

TEST(DiscretePath, NodeRotationGradientIsExact) {
  // Reference: R_f - R_i = R_i Skew(theta) S(theta) = sum_j theta_j R_i Skew(e_j) S(theta), |theta| up to 2.5 rad.
  ExpectExactDiscreteGradient<3>(RotationA, 2.5, 101);
  ExpectExactDiscreteGradient<3>(RotationB, 2.5, 102);
}

TEST(DiscretePath, NodeRotationGradientIsExactForTinyRotations) {
  // Reference: as above, with |theta| < 1e-6 where S and T use their series.
  ExpectExactDiscreteGradient<3>(RotationA, 1.0e-6, 103);
}

TEST(DiscretePath, NodeRotationDerivativeMatchesFiniteDifference) {
  // Reference: d R_f / d theta_j = R_f Skew(T e_j), checked by central differences of R_i Exp(theta).
  ExpectDerivativeMatchesFiniteDifference<3>(RotationA, 2.5, 104);
  ExpectDerivativeMatchesFiniteDifference<3>(RotationB, 2.5, 105);
}

TEST(DiscretePath, NodePositionGradientIsExact) {
  // Reference: x_f - x_i = dx.
  ExpectExactDiscreteGradient<1>(PositionA, 1.0, 106);
  ExpectExactDiscreteGradient<1>(PositionB, 1.0, 107);
}

TEST(DiscretePath, NodePositionDerivativeMatchesFiniteDifference) {
  // Reference: d x_f / d dx = I.
  ExpectDerivativeMatchesFiniteDifference<1>(PositionA, 1.0, 108);
  ExpectDerivativeMatchesFiniteDifference<1>(PositionB, 1.0, 109);
}

TEST(DiscretePath, AxisRotationGradientIsExactForLargeSteps) {
  // Reference: Rot(q_f) - Rot(q_i) = Rot(q_m) Skew(a) 2 sin(dq/2), for dq up to 2 rad and beyond pi.
  test::Random random(110);
  for (double dq : {1.0e-12, 1.0e-6, 0.3, -2.0, 2.0, 3.5, -6.0}) {
    const double q_i = random.Uniform(-M_PI, M_PI);
    const MatrixPath p = AxisRotationPath(FixedAxis(), q_i, q_i + dq, 1);
    EXPECT_LT(test::MaxAbs(p.f - p.i - p.gradient(1) * dq), kExactIdentity) << "dq " << dq;
    EXPECT_TRUE(p.gradient(0).isZero(0.0) && p.gradient(2).isZero(0.0));
  }
  ExpectExactDiscreteGradient<3>(AxisRotation, 2.0, 111);
}

TEST(DiscretePath, AxisRotationDerivativeMatchesFiniteDifference) {
  // Reference: d Rot(a, q_f) / d q_f = Rot(a, q_f) Skew(a).
  ExpectDerivativeMatchesFiniteDifference<3>(AxisRotation, 2.0, 112);
}

TEST(DiscretePath, LinearPathGradientIsExact) {
  // Reference: sum_k c_k q_k is linear: its change is sum_k c_k dq_k.
  ExpectExactDiscreteGradient<1>(Linear, 2.0, 113);
}

TEST(DiscretePath, LinearPathDerivativeMatchesFiniteDifference) {
  // Reference: d (sum_k c_k q_k) / d q_k = c_k.
  ExpectDerivativeMatchesFiniteDifference<1>(Linear, 2.0, 114);
}

TEST(DiscretePath, TransposedProductGradientIsExact) {
  // Reference: midpoint product rule (AB)_f - (AB)_i = A_m dB + dA B_m, applied to Transpose(R_a) R_b d.
  ExpectExactDiscreteGradient<1>(RelativeVector, 2.0, 115);
}

TEST(DiscretePath, TransposedProductDerivativeMatchesFiniteDifference) {
  // Reference: product rule d(AB)_f = A_f dB_f + dA_f B_f for Transpose(R_a) R_b d.
  ExpectDerivativeMatchesFiniteDifference<1>(RelativeVector, 2.0, 116);
}

TEST(DiscretePath, JointRotationChainGradientIsExact) {
  // Reference: nested midpoint products Rel^T R_aJ^T R_a^T R_b R_bJ with two axis rotations, large steps.
  ExpectExactDiscreteGradient<3>(JointRotationChain, 2.0, 117);
}

TEST(DiscretePath, JointRotationChainDerivativeMatchesFiniteDifference) {
  // Reference: central differences of the end value of the chain above.
  ExpectDerivativeMatchesFiniteDifference<3>(JointRotationChain, 2.0, 118);
}

TEST(DiscretePath, JointPositionChainGradientIsExact) {
  // Reference: sums, differences and products of node, axis and linear paths keep the identity exact.
  ExpectExactDiscreteGradient<1>(JointPositionChain, 2.0, 119);
}

TEST(DiscretePath, JointPositionChainDerivativeMatchesFiniteDifference) {
  // Reference: central differences of the end value of the chain above.
  ExpectDerivativeMatchesFiniteDifference<1>(JointPositionChain, 2.0, 120);
}

}  // namespace discrete_path_test
}  // namespace flexmbd
