#pragma once
// Shared helpers of the unit tests: seeded random inputs and finite-difference utilities. Every random draw
// comes from a fixed seed, so a failure reproduces exactly.

#include <cmath>
#include <random>

#include <Eigen/Core>

#include "flexmbd/elements/element.hpp"
#include "flexmbd/math/so3.hpp"
#include "flexmbd/model/state.hpp"

namespace flexmbd {
namespace test {

// Seeded uniform random numbers.
class Random {
 public:
  explicit Random(unsigned seed) : engine_(seed) {}

  double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }

  // Components uniform in [-scale, scale].
  Vec3 Vector(double scale) { return Vec3(Uniform(-scale, scale), Uniform(-scale, scale), Uniform(-scale, scale)); }

  Eigen::VectorXd VectorX(int n, double scale) {
    Eigen::VectorXd v(n);
    for (int k = 0; k < n; ++k) v[k] = Uniform(-scale, scale);
    return v;
  }

  // Uniformly distributed direction.
  Vec3 UnitVector() {
    Vec3 v;
    do {
      v = Vector(1.0);
    } while (v.norm() < 0.1 || v.norm() > 1.0);
    return v.normalized();
  }

  // A rotation by an angle in [0, pi) about a random axis.
  Mat3 Rotation() { return Exp(Uniform(0.0, M_PI) * UnitVector()); }

  // A node state with random pose and velocities of the given scales.
  NodeState Node(double position_scale, double velocity_scale) {
    NodeState n;
    n.x = Vector(position_scale);
    n.R = Rotation();
    n.v = Vector(velocity_scale);
    n.w = Vector(velocity_scale);
    return n;
  }

 private:
  std::mt19937 engine_;
};

// Largest absolute entry, or 0 for an empty matrix.
template <typename Derived>
double MaxAbs(const Eigen::MatrixBase<Derived>& m) {
  return m.size() == 0 ? 0.0 : m.cwiseAbs().maxCoeff();
}

// An element's local residual (AddResidual) and tangent (AddTangent) for a context, from zero.
inline Eigen::VectorXd LocalResidual(const Element& e, const StepContext& ctx) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(e.num_local()), magnitude = Eigen::VectorXd::Zero(e.num_local());
  e.AddResidual(ctx, r, magnitude);
  return r;
}

inline Eigen::MatrixXd LocalTangent(const Element& e, const StepContext& ctx) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(e.num_local(), e.num_local());
  e.AddTangent(ctx, J);
  return J;
}

}  // namespace test
}  // namespace flexmbd
