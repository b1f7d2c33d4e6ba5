#include "flexmbd/solver/smoothed_rates.hpp"

#include <array>

#include <Eigen/LU>

#include "flexmbd/math/so3.hpp"

namespace flexmbd {
namespace {

// The constant body twist (nu, omega) of a screw motion from rotation R_i over a step of size h with spatial
// rotation vector phi and displacement dx: R_f = R_i Exp(psi), psi = h omega, and x_f - x_i = R_i J(psi) h nu with
// J(psi) = int_0^1 Exp(s psi) ds, the transpose of the right Jacobian.
struct BodyTwist {
  Vec3 nu = Vec3::Zero(), omega = Vec3::Zero();
};

BodyTwist TwistOfStep(const Mat3& R_i, const Vec3& phi, const Vec3& dx, double h) {
  const Vec3 psi = R_i.transpose() * phi;
  const Mat3 J = RightJacobian(psi).transpose();
  return {J.partialPivLu().solve(R_i.transpose() * dx) / h, psi / h};
}

}  // namespace

State WithSmoothedRates(const State& end) {
  if (end.history_steps < 3) return end;
  const std::array<double, 3>& h = end.recent_h;
  // Midpoints of the last three steps, relative to the end; the weights of the parabola through them at 0.
  const std::array<double, 3> m = {-0.5 * h[0], -h[0] - 0.5 * h[1], -h[0] - h[1] - 0.5 * h[2]};
  std::array<double, 3> weight;
  for (int j = 0; j < 3; ++j) {
    const double a = m[(j + 1) % 3], b = m[(j + 2) % 3];
    weight[j] = a * b / ((m[j] - a) * (m[j] - b));
  }
  State smoothed = end;
  for (NodeState& node : smoothed.nodes) {
    // Walk back from the end rotation: R_f^T phi is the newest step's body rotation vector psi (Exp(-psi) leaves
    // psi unchanged), and R_f Exp(-psi) is that step's start, the end of the step before.
    Mat3 step_end = node.R;
    BodyTwist twist;
    for (int j = 0; j < 3; ++j) {
      const Vec3 phi = h[j] * node.mean_w[j];
      const Mat3 step_start = step_end * Exp(-step_end.transpose() * phi);
      const BodyTwist step = TwistOfStep(step_start, phi, h[j] * node.mean_v[j], h[j]);
      twist.nu += weight[j] * step.nu;
      twist.omega += weight[j] * step.omega;
      step_end = step_start;
    }
    node.v = node.R * twist.nu;
    node.w = twist.omega;
  }
  smoothed.qdot = weight[0] * end.mean_qdot[0] + weight[1] * end.mean_qdot[1] + weight[2] * end.mean_qdot[2];
  smoothed.element_state_rates = weight[0] * end.mean_state_rate[0] + weight[1] * end.mean_state_rate[1] +
                                 weight[2] * end.mean_state_rate[2];
  return smoothed;
}

}  // namespace flexmbd
