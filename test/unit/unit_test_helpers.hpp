#pragma once
// Shared helpers of the unit tests: seeded random inputs and finite-difference utilities. Every random draw
// comes from a fixed seed, so a failure reproduces exactly.

#include <cmath>
#include <random>
#include <vector>

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

// An element's local residual (AddResidual) and whole tangent (AddSchemeTangent) for a context, from zero.
inline Eigen::VectorXd LocalResidual(const Element& e, const StepContext& ctx) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(e.num_local()), magnitude = Eigen::VectorXd::Zero(e.num_local());
  e.AddResidual(ctx, r, magnitude);
  return r;
}

inline Eigen::MatrixXd LocalTangent(const Element& e, const StepContext& ctx) {
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(e.num_local(), e.num_local());
  AddSchemeTangent(e, ctx, J);
  return J;
}

// Central differences of an element's residual with respect to the end rates (v_f, w_f, qdot_f, element state
// rates), or with
// `accelerations` the end accelerations (vdot_f, wdot_f), of each local unknown, all else held: the reference
// for Element::AddRateParts. Multiplier columns and variable accelerations are left zero (no element reads them).
inline Eigen::MatrixXd RateDifferences(const Element& e, StepContext ctx, bool accelerations, double step) {
  std::vector<NodeStep> nodes = ctx.nodes != nullptr ? *ctx.nodes : std::vector<NodeStep>{};
  std::vector<VariableStep> variables = ctx.variables != nullptr ? *ctx.variables : std::vector<VariableStep>{};
  std::vector<ElementStateStep> states =
      ctx.element_states != nullptr ? *ctx.element_states : std::vector<ElementStateStep>{};
  ctx.nodes = &nodes;
  ctx.variables = &variables;
  ctx.element_states = &states;
  const int node_unknowns = 6 * static_cast<int>(nodes.size());
  const int state_unknowns = node_unknowns + static_cast<int>(variables.size());
  Eigen::MatrixXd differences = Eigen::MatrixXd::Zero(e.num_local(), e.num_local());
  for (int j = 0; j < e.num_local(); ++j) {
    const int u = e.unknowns()[j];
    double* rate = nullptr;
    if (u < node_unknowns) {
      NodeStep& s = nodes[u / 6];
      Vec3& moved = u % 6 < 3 ? (accelerations ? s.vdot_f : s.v_f) : (accelerations ? s.wdot_f : s.w_f);
      rate = &moved[u % 3];
    } else if (u - node_unknowns < static_cast<int>(variables.size()) && !accelerations) {
      rate = &variables[u - node_unknowns].qdot_f;
    } else if (u - state_unknowns >= 0 && u - state_unknowns < static_cast<int>(states.size()) && !accelerations) {
      rate = &states[u - state_unknowns].rate;
    }
    if (rate == nullptr) continue;
    const double held = *rate;
    *rate = held + step;
    const Eigen::VectorXd plus = LocalResidual(e, ctx);
    *rate = held - step;
    differences.col(j) = (plus - LocalResidual(e, ctx)) / (2.0 * step);
    *rate = held;
  }
  return differences;
}

// Central differences of an element's residual over its local unknowns, moving the global unknown vector
// `unknowns` and taking the context from `context(moved unknowns)`: the reference for a whole tangent.
template <class Context>
Eigen::MatrixXd UnknownDifferences(const Element& e, const Eigen::VectorXd& unknowns, const Context& context,
                                   double step) {
  Eigen::MatrixXd out(e.num_local(), e.num_local());
  for (int j = 0; j < e.num_local(); ++j) {
    Eigen::VectorXd moved = unknowns;
    moved[e.unknowns()[j]] += step;
    const Eigen::VectorXd plus = LocalResidual(e, context(moved));
    moved[e.unknowns()[j]] -= 2 * step;
    out.col(j) = (plus - LocalResidual(e, context(moved))) / (2 * step);
  }
  return out;
}

// An element's rate parts (AddRateParts), from zero.
struct RateParts {
  Eigen::MatrixXd D, M;
};
inline RateParts LocalRateParts(const Element& e, const StepContext& ctx) {
  RateParts parts{Eigen::MatrixXd::Zero(e.num_local(), e.num_local()),
                  Eigen::MatrixXd::Zero(e.num_local(), e.num_local())};
  if (e.HasRateParts(ctx.mode)) e.AddRateParts(ctx, parts.D, parts.M);
  return parts;
}

}  // namespace test
}  // namespace flexmbd
