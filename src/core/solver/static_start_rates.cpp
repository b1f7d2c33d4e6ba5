// Rates of a static start (docs/theory.md (K4)): the drives' rates, the rest at rest relative to its carriers.

#include "flexmbd/solver/static_start_rates.hpp"

#include <Eigen/QR>

#include <string>

#include "constraint_null_space.hpp"
#include "drive_rows.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"

namespace flexmbd {
namespace {
// Rest rows that the constraints leave independent of each other down to this fraction of the largest singular
// value count; below it a direction is taken as one they do not reach, and left at rest (minimum norm).
constexpr double kRankTolerance = 1.0e-10;
// Largest n solved (dense, O(n^3)): about half a minute on two cores (theory (K4): 21 s at n = 1813).
constexpr int kDenseStartLimit = 2000;

// The conditions of rest over u = (v in W, w in the node frame, per node; qdot): an undriven variable's rate, a
// spherical joint's relative angular velocity (in W), and each beam node's departure from the rigid motion of its
// beam's root (translation and rotation, in W).
Eigen::MatrixXd RestRows(const Model& model, const State& state) {
  const int nq = model.element_state_unknown(0);
  int rows = 0;
  for (int v = 0; v < model.num_variables(); ++v) rows += model.driven(v) ? 0 : 1;
  for (const Joint* joint : model.joints()) rows += joint->kinematics().rotation_constrained ? 0 : 3;
  for (const BeamInfo& beam : model.beams()) rows += 6 * (static_cast<int>(beam.nodes.size()) - 1);
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(rows, nq);
  int row = 0;
  for (int v = 0; v < model.num_variables(); ++v) {
    if (!model.driven(v)) S(row++, model.variable_unknown(v)) = 1.0;
  }
  // w in W of a node is R w; the world has none
  auto add_spin = [&](int node, double sign) {
    if (node >= 0) S.block<3, 3>(row, model.node_unknown(node) + 3) += sign * state.nodes[node].R;
  };
  for (const Joint* joint : model.joints()) {
    if (joint->kinematics().rotation_constrained) continue;
    add_spin(joint->child().node, 1.0);
    add_spin(joint->parent().node, -1.0);
    row += 3;
  }
  for (const BeamInfo& beam : model.beams()) {
    const int root = beam.nodes.front();
    const NodeState& r = state.nodes[root];
    for (size_t k = 1; k < beam.nodes.size(); ++k) {
      const int node = beam.nodes[k];
      // v_k - v_0 - (R_0 w_0) x (x_k - x_0)
      S.block<3, 3>(row, model.node_unknown(node)) = Mat3::Identity();
      S.block<3, 3>(row, model.node_unknown(root)) = -Mat3::Identity();
      S.block<3, 3>(row, model.node_unknown(root) + 3) = Skew(state.nodes[node].x - r.x) * r.R;
      row += 3;
      add_spin(node, 1.0);
      add_spin(root, -1.0);
      row += 3;
    }
  }
  return S;
}
}  // namespace

void SetStaticStartRates(const Model& model, State* state) {
  // A drive's row q - f(t) holds at rate f'(t); no other row depends on time.
  const Eigen::VectorXd row_rates = DriveLawDerivatives(model, *state, 1);
  if (row_rates.isZero(0.0)) return;
  const int nq = model.element_state_unknown(0), nv = model.num_variables();
  if (nq > kDenseStartLimit) {
    throw SolverError("static start: a drive moves at the start, and the rates that follow it are solved densely, "
                      "up to " + std::to_string(kDenseStartLimit) + " kinematic unknowns; this model has " +
                      std::to_string(nq) + ". Expected a drive at rest at the start (a cosine_ramp), or "
                      "solver.static_first: false");
  }
  // The constraint rows' Jacobian over the unknowns' own rates (v in W): B of the linearisation, whose node
  // translations are in the node frame (theory (E3)), turned back.
  const LinearisedSystem linearised = Linearise(model, *state, ReferenceMotion::kZeroAcceleration);
  const Eigen::MatrixXd B = Eigen::MatrixXd(linearised.B * linearised.T.transpose()).leftCols(nq);
  const ConstraintNullSpace constraints(B, nq);
  const Eigen::VectorXd particular = constraints.MinimumNormSolution(row_rates);
  // Within the motions that keep the constraints, particular + Z y, the least departure from rest; the smallest
  // such y leaves at rest what no rest row reaches (a body that nothing holds).
  const Eigen::MatrixXd S = RestRows(model, *state);
  const Eigen::MatrixXd& Z = constraints.Z();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(Z.cols());
  if (S.rows() > 0 && Z.cols() > 0) {
    Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> rest(S * Z);
    rest.setThreshold(kRankTolerance);
    y = rest.solve(-S * particular);
  }
  const Eigen::VectorXd u = particular + Z * y;
  for (int k = 0; k < model.num_nodes(); ++k) {
    state->nodes[k].v = u.segment<3>(model.node_unknown(k));
    state->nodes[k].w = u.segment<3>(model.node_unknown(k) + 3);
  }
  state->qdot = u.segment(model.variable_unknown(0), nv);
}

}  // namespace flexmbd
