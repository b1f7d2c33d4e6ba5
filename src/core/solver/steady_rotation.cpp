// Steady rotation and eigen-analysis about it (docs/theory.md, "Steady rotation", eqs. (R1)-(R4)).

#include "flexmbd/solver/steady_rotation.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "eigen_internal.hpp"
#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// A node is at rest, or turns with the spin, when its velocities differ from that by less than this fraction of
// the spin (angular) or of the spin times the model's length scale (linear): the initial placement computes
// them from the joint rates to round-off.
constexpr double kRigidMotionTolerance = 1.0e-9;
// Newton on the steady configuration stops when no increment exceeds this fraction of the length scale (node
// translations) or of one radian (rotations, joint variables): it converges quadratically, so the
// configuration is then good to round-off.
constexpr double kIncrementTolerance = 1.0e-10;

std::string Number(double value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.6g", value);
  return text;
}

std::string Where(const Model& model) {
  return model.source() + ": joints.*.initial.velocity: ";
}

// Holds the spinning variable in the Newton system and the eigen-analysis unless a drive holds it already.
bool Held(const Model& model, const SteadyRotation& rotation) { return !model.driven(rotation.spinning_variable); }

}  // namespace

SteadyRotation SteadyRotationOf(const Model& model, const State& state) {
  SteadyRotation out;
  std::string spinning;
  for (int v = 0; v < model.num_variables(); ++v) {
    if (state.qdot.size() != model.num_variables() || state.qdot[v] == 0.0) continue;
    if (out.spinning_variable >= 0) {
      throw ConfigError(Where(model) + "a steady rotation has one spinning joint, but " + spinning + " and " +
                        model.variable_names()[v] + " both have a rate; expected one non-zero initial velocity");
    }
    out.spinning_variable = v;
    spinning = model.variable_names()[v];
  }
  if (out.spinning_variable < 0) {
    throw ConfigError(Where(model) + "no joint has a rate; expected one joint (the hub) with a non-zero "
                      "initial.velocity for an analysis about a steady rotation");
  }
  // The spin: the angular velocity of the fastest-turning node, its axis through that node's circle centre.
  int fastest = 0;
  for (int k = 1; k < model.num_nodes(); ++k) {
    if (state.nodes[k].w.norm() > state.nodes[fastest].w.norm()) fastest = k;
  }
  const NodeState& f = state.nodes[fastest];
  const Vec3 omega = f.R * f.w;
  out.speed = omega.norm();
  if (!(out.speed > 0)) {
    throw ConfigError(Where(model) + "the rate of " + spinning + " turns no node; expected a joint that carries "
                      "the rotating part");
  }
  out.axis_W = omega / out.speed;
  out.variable_sense = state.qdot[out.spinning_variable] / out.speed;
  out.center_W = f.x + omega.cross(f.v) / (out.speed * out.speed);
  const double angular_tolerance = kRigidMotionTolerance * out.speed;
  const double linear_tolerance = angular_tolerance * model.length_scale();
  out.rotating.assign(model.num_nodes(), false);
  for (int k = 0; k < model.num_nodes(); ++k) {
    const NodeState& n = state.nodes[k];
    const bool at_rest = n.w.norm() <= angular_tolerance && n.v.norm() <= linear_tolerance;
    const bool turning = (n.R * n.w - omega).norm() <= angular_tolerance &&
                         (n.v - omega.cross(n.x - out.center_W)).norm() <= linear_tolerance;
    if (!at_rest && !turning) {
      throw ConfigError(Where(model) + model.node_name(k) + " neither rests nor turns with " + spinning +
                        " about one fixed axis; expected a rate on the hub joint only, whose parent is at rest");
    }
    out.rotating[k] = turning;
  }
  return out;
}

SteadyRotation ScaleSpeed(const SteadyRotation& rotation, double factor) {
  SteadyRotation out = rotation;
  out.speed *= factor;
  return out;
}

State WithSteadyMotion(const Model& model, const State& state, const SteadyRotation& rotation) {
  State out = state;
  const Vec3 omega = rotation.speed * rotation.axis_W;
  for (int k = 0; k < model.num_nodes(); ++k) {
    NodeState& n = out.nodes[k];
    const bool turning = rotation.rotating[k];
    n.v = turning ? Vec3(omega.cross(n.x - rotation.center_W)) : Vec3::Zero();
    n.w = turning ? Vec3(n.R.transpose() * omega) : Vec3::Zero();
    n.a_prev = omega.cross(n.v);
    n.alpha_prev.setZero();
  }
  out.qdot = Eigen::VectorXd::Zero(model.num_variables());
  out.qdot[rotation.spinning_variable] = rotation.variable_sense * rotation.speed;
  out.qddot_prev = Eigen::VectorXd::Zero(model.num_variables());
  if (out.lambda.size() != model.num_multipliers()) out.lambda = Eigen::VectorXd::Zero(model.num_multipliers());
  return out;
}

namespace {

// The largest increment of a Newton iteration (translations over the length scale) and its unknown.
struct Increment {
  double largest = 0;
  int unknown = 0;
};

// One Newton iteration of (R2): solves [K G^T e_h; B C 0; e_h^T 0 0] (y, dlambda, tau) = -(r, Phi, 0) with the
// hold column e_h on the spinning variable (when held), and applies y and dlambda. `hub_effort` receives tau. C
// holds lambda = 0 on the rows of inactive constraints (open rigid stops), as the static analysis's tangent does.
Increment NewtonIteration(const Model& model, const SteadyRotation& rotation, State* state, double* hub_effort) {
  const LinearisedSystem s = Linearise(model, *state, ReferenceMotion::kFromState);
  const int nk = static_cast<int>(s.K.rows()), m = static_cast<int>(s.B.rows());
  const bool held = Held(model, rotation);
  const int n = nk + m + (held ? 1 : 0);
  Triplets t;
  auto add = [&t](const Eigen::SparseMatrix<double>& A, int row, int col) {
    for (int j = 0; j < A.outerSize(); ++j) {
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, j); it; ++it) {
        t.emplace_back(row + it.row(), col + j, it.value());
      }
    }
  };
  add(s.K, 0, 0);
  add(Eigen::SparseMatrix<double>(s.B.transpose()), 0, nk);  // constraint forces: G = B at the end point (E1)
  add(s.B, nk, 0);
  add(s.C, nk, nk);
  const int hub = model.variable_unknown(rotation.spinning_variable);
  if (held) {
    t.emplace_back(hub, nk + m, 1.0);
    t.emplace_back(nk + m, hub, 1.0);
  }
  Eigen::SparseMatrix<double> A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  Eigen::VectorXd step = Eigen::VectorXd::Zero(n);
  step.head(nk + m) = -s.residual;
  eigen_internal::KluLu lu;
  if (!lu.Factorise(A) || !lu.Solve(&step)) {
    throw SolverError("steady rotation at " + Number(rotation.speed) +
                      " rad/s: the Newton matrix is singular (a part free to move without stiffness, or "
                      "dependent constraints)");
  }
  const Eigen::VectorXd dx = s.T * step.head(nk);
  Eigen::VectorXd relative = dx.cwiseAbs();
  for (int k = 0; k < model.num_nodes(); ++k) {
    NodeState& node = state->nodes[k];
    node.x += dx.segment<3>(model.node_unknown(k));
    node.R = node.R * Exp(dx.segment<3>(model.node_unknown(k) + 3));
    relative.segment<3>(model.node_unknown(k)) /= model.length_scale();
  }
  for (int v = 0; v < model.num_variables(); ++v) state->q[v] += dx[model.variable_unknown(v)];
  state->lambda += step.segment(nk, m);
  if (held) *hub_effort = step[nk + m];  // r holds no effort of its own: tau is the whole of it
  Increment out;
  if (nk > 0) out.largest = relative.maxCoeff(&out.unknown);
  return out;
}

}  // namespace

SteadyResult SolveSteadyRotation(const Model& model, const State& start, const SteadyRotation& rotation) {
  SteadyResult out;
  // Consistent multipliers at rest first: with zero ones the first tangent lacks the joints' geometric stiffness.
  out.state = WithConsistentMotion(model, WithSteadyMotion(model, start, ScaleSpeed(rotation, 0.0)));
  const int steps = model.solver().load_steps;
  for (int step = 1; step <= steps; ++step) {
    const SteadyRotation at = ScaleSpeed(rotation, static_cast<double>(step) / steps);
    bool converged = false;
    for (int iteration = 0; iteration < model.solver().max_iterations && !converged; ++iteration) {
      out.state = WithSteadyMotion(model, out.state, at);
      const Increment increment = NewtonIteration(model, at, &out.state, &out.hub_effort);
      ++out.iterations;
      converged = increment.largest <= kIncrementTolerance;
      if (!converged && iteration + 1 == model.solver().max_iterations) {
        throw SolverError("steady rotation at " + Number(at.speed) + " rad/s did not converge in " +
                          std::to_string(iteration + 1) + " Newton iterations (solver.max_iterations); last " +
                          "increment " + Number(increment.largest) + " at " + model.DescribeUnknown(increment.unknown));
      }
    }
  }
  out.state = WithSteadyMotion(model, out.state, rotation);
  return out;
}

EigenResult EigenAnalysisAboutSteadyRotation(const Model& model, const State& steady, const SteadyRotation& rotation,
                                             const EigenOptions& options) {
  LinearisedSystem system = Linearise(model, steady, ReferenceMotion::kFromState);
  if (!Held(model, rotation)) return SolveModes(model, system, options);
  // (R3): the hold row dq = 0 on the spinning variable joins the constraints.
  const int nk = static_cast<int>(system.B.cols()), m = static_cast<int>(system.B.rows());
  Eigen::SparseMatrix<double> B(m + 1, nk);
  Triplets t;
  for (int j = 0; j < nk; ++j) {
    for (Eigen::SparseMatrix<double>::InnerIterator it(system.B, j); it; ++it) t.emplace_back(it.row(), j, it.value());
  }
  t.emplace_back(m, model.variable_unknown(rotation.spinning_variable), 1.0);
  B.setFromTriplets(t.begin(), t.end());
  system.B = B;
  EigenResult result = SolveModes(model, system, options);
  // (R4): the rigid rotation about the spin axis, per radian, as the first mode.
  Mode rigid;
  rigid.rigid_body = true;
  Eigen::VectorXd shape = Eigen::VectorXd::Zero(nk);
  for (int k = 0; k < model.num_nodes(); ++k) {
    if (!rotation.rotating[k]) continue;
    const NodeState& n = steady.nodes[k];
    shape.segment<3>(model.node_unknown(k)) = rotation.axis_W.cross(n.x - rotation.center_W);
    shape.segment<3>(model.node_unknown(k) + 3) = n.R.transpose() * rotation.axis_W;
  }
  shape[model.variable_unknown(rotation.spinning_variable)] = rotation.variable_sense;
  rigid.shape = (shape / shape.cwiseAbs().maxCoeff()).cast<std::complex<double>>();
  result.modes.insert(result.modes.begin(), rigid);
  if (options.num_modes > 0 && static_cast<int>(result.modes.size()) > options.num_modes) {
    result.modes.resize(options.num_modes);
  }
  ++result.num_rigid_body;
  ++result.num_dof;
  return result;
}

std::vector<SweepPoint> SteadyRotationSweep(const Model& model, const State& start, const SteadyRotation& rotation,
                                            const std::vector<double>& factors, const EigenOptions& options) {
  std::vector<SweepPoint> points;
  for (double factor : factors) {
    const SteadyRotation at = ScaleSpeed(rotation, factor);
    points.push_back({factor, EigenAnalysisAboutSteadyRotation(model, SolveSteadyRotation(model, start, at).state, at,
                                                               options)});
  }
  TrackModes(&points);
  return points;
}

}  // namespace flexmbd
