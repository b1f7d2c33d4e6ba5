#include "flexmbd/solver/time_integrator.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/energy_decaying_integrator.hpp"
#include "flexmbd/solver/generalized_alpha_integrator.hpp"

namespace flexmbd {
namespace {
// Default error floors: this fraction of error_tol times the length scale (positions) or one radian.
constexpr double kDefaultFloorFraction = 1.0e-3;

double FloorOrDefault(double floor, double error_tol, double unit) {
  return floor > 0 ? floor : kDefaultFloorFraction * error_tol * unit;
}

// Midpoint of a node's step j (0 the newest), walked back from its end position over its mean rates.
Vec3 StepMidpoint(const NodeState& n, const std::array<double, 3>& h, int j) {
  Vec3 x = n.x;
  for (int i = 0; i < j; ++i) x -= h[i] * n.mean_v[i];
  return x - 0.5 * h[j] * n.mean_v[j];
}

// A beam's rigid motion over each of the last three steps (T12b): the rigid velocity field that fits its nodes' mean
// rates best (least squares) about the mean of their step midpoints, its spin about the beam's own chord (which
// the rates of nodes in a row do not fix) the nodes' mean spin there; and the largest deformation rate and spin
// relative to it of its nodes in the newest step.
struct BeamRigidMotion {
  std::array<Vec3, 3> rate, spin, centre;
  double largest_rate = 0, largest_spin = 0;

  BeamRigidMotion(const BeamInfo& beam, const State& end, const std::array<double, 3>& h) {
    const double count = static_cast<double>(beam.nodes.size());
    for (int j = 0; j < 3; ++j) {
      rate[j] = centre[j] = Vec3::Zero();
      Vec3 mean_spin = Vec3::Zero();
      for (int k : beam.nodes) {
        rate[j] += end.nodes[k].mean_v[j] / count;
        mean_spin += end.nodes[k].mean_w[j] / count;
        centre[j] += StepMidpoint(end.nodes[k], h, j) / count;
      }
      // Normal equations of min sum_n |u_n - rate - spin x r_n|^2: sum_n (|r_n|^2 I - r_n r_n^T) spin =
      // sum_n r_n x (u_n - rate), singular along the chord a of a straight beam; there the spin is the mean spin's
      // (the term s a a^T, s = sum_n |r_n|^2, makes the matrix s I for a straight beam).
      Mat3 normal = Mat3::Zero();
      Vec3 moment = Vec3::Zero();
      double s = 0;
      for (int k : beam.nodes) {
        const Vec3 r = StepMidpoint(end.nodes[k], h, j) - centre[j];
        normal += r.squaredNorm() * Mat3::Identity() - r * r.transpose();
        moment += r.cross(end.nodes[k].mean_v[j] - rate[j]);
        s += r.squaredNorm();
      }
      const Vec3 chord =
          StepMidpoint(end.nodes[beam.nodes.back()], h, j) - StepMidpoint(end.nodes[beam.nodes.front()], h, j);
      const Vec3 a = chord.norm() > 0 ? Vec3(chord.normalized()) : Vec3::UnitX();
      normal += s * a * a.transpose();
      moment += s * a * a.dot(mean_spin);
      spin[j] = s > 0 ? Vec3(normal.ldlt().solve(moment)) : mean_spin;
    }
    for (int k : beam.nodes) {
      largest_rate = std::max(largest_rate, DeformationRate(end.nodes[k], h, 0).norm());
      largest_spin = std::max(largest_spin, DeformationSpin(end.nodes[k], 0).norm());
    }
  }
  // A node's mean rate and spin over step j less the rigid motion's there.
  Vec3 DeformationRate(const NodeState& n, const std::array<double, 3>& h, int j) const {
    return n.mean_v[j] - rate[j] - spin[j].cross(StepMidpoint(n, h, j) - centre[j]);
  }
  Vec3 DeformationSpin(const NodeState& n, int j) const { return n.mean_w[j] - spin[j]; }
};
}  // namespace

double JointErrorFloor(const SolverSpec& solver) {
  return FloorOrDefault(solver.error_floor.joint, solver.error_tol, 1.0);
}

double JointErrorScale(const SolverSpec& solver, double h, double peak_rate) {
  return JointErrorFloor(solver) + solver.error_tol * h * peak_rate;
}

double AlternatingOffset(double newest, double middle, double oldest, const std::array<double, 3>& h) {
  // The differences of the mean rates over the spans between the midpoints: (newest - middle) = a s_1 + 2x (1/h_0 +
  // 1/h_1), (middle - oldest) = a s_2 - 2x (1/h_1 + 1/h_2), a the second derivative; eliminating a gives x.
  const double span_newer = 0.5 * (h[0] + h[1]), span_older = 0.5 * (h[1] + h[2]);
  const double newer = (1 / h[0] + 1 / h[1]) / span_newer, older = (1 / h[1] + 1 / h[2]) / span_older;
  return ((newest - middle) / span_newer - (middle - oldest) / span_older) / (2 * (newer + older));
}

double StepAfterJump(const SolverSpec& solver, double acceleration_jump, double peak_rate) {
  const double jump = std::abs(acceleration_jump);
  if (!solver.adaptive || jump == 0) return std::numeric_limits<double>::infinity();
  // The positive root of jump h^2 / 24 - relative h - floor = 0.
  const double relative = solver.error_tol * peak_rate;
  return 12.0 * (relative + std::sqrt(relative * relative + jump * JointErrorFloor(solver) / 6.0)) / jump;
}

const char* StepStatusName(StepStatus status) {
  switch (status) {
    case StepStatus::kAccepted: return "accepted";
    case StepStatus::kRejectedError: return "local error above tolerance";
    case StepStatus::kRejectedEvent: return "stop or friction event";
    case StepStatus::kNewtonDiverged: return "Newton did not converge";
    case StepStatus::kSingularMatrix: return "singular iteration matrix";
  }
  return "unknown";
}

std::unique_ptr<TimeIntegrator> MakeTimeIntegrator(const Model& model, SparseSystem* system) {
  if (model.solver().integrator == SolverSpec::Integrator::kGeneralizedAlpha) {
    return std::make_unique<GeneralizedAlphaIntegrator>(model, system);
  }
  return std::make_unique<EnergyDecayingIntegrator>(model, system);
}

ErrorEstimate EstimateLocalError(const Model& model, const State& end) {
  ErrorEstimate estimate;
  if (end.history_steps < 3) {
    estimate.error = std::numeric_limits<double>::quiet_NaN();
    return estimate;
  }
  const SolverSpec& solver = model.solver();
  const double rtol = solver.error_tol;
  const std::array<double, 3>& h = end.recent_h;
  // Mean rates are the rates at the step midpoints (to O(h^2)); their second divided difference over the three
  // midpoints is the third derivative of the motion, and the local error of the trapezoidal family is h^3 x^(3) / 12.
  const double span_newer = 0.5 * (h[0] + h[1]);
  auto third_derivative = [&](const auto& newest, const auto& middle, const auto& oldest) {
    return MeanRateThirdDerivative(newest, middle, oldest, h);
  };
  const double weight = h[0] * h[0] * h[0] / 12.0;
  // Each entry is compared with its floor plus rtol times the step's travel at the run's peak rate of its kind (of
  // its own for a joint variable: a slow joint beside a fast one is judged on its own motion). Algebraic rotations
  // (beam nodes without rotary inertia) and the joint variables on them are left out, as implicit DAE codes leave out
  // algebraic variables: the midpoint equations leave them an alternating error that no step size removes, which
  // the estimate reads as a third derivative of the same size at every step; the bodies and translations they join
  // carry the motion's error (docs/theory.md, "Algebraic rotations").
  const double position_scale = FloorOrDefault(solver.error_floor.position, rtol, model.length_scale()) +
                                rtol * h[0] * end.peak_speed;
  const double rotation_scale = FloorOrDefault(solver.error_floor.rotation, rtol, 1.0) + rtol * h[0] * end.peak_spin;
  double sum = 0, worst = -1;
  int count = 0;
  auto add = [&](double local_error, double scale, int unknown) {
    const double ratio = local_error / scale;
    sum += ratio * ratio;
    ++count;
    if (ratio > worst) {
      worst = ratio;
      estimate.worst_unknown = unknown;
    }
  };
  // A damped beam's deformation decays at mu omega^2 / 2, omega^2 = |x_d'''| / |x_d'| for one mode (x_d' taken as
  // the beam's largest deformation rate): the error a step leaves in it adds up over 1 / that rate, and is discounted
  // by its ratio to the horizon over which an undamped error adds up (T12b). The relative tolerance lets that grow by
  // error_tol times the peak speed per unit time, so the horizon is the time the motion takes to move by the model's
  // size at its peak speed (by a radian at its peak spin while no node has moved): the damped mode keeps error_tol
  // of that size; or the time run so far, if longer. Not the time left to t_end: every step, and every sample, then
  // depended on where the run ends. A mode's local error is a phase error: besides the position part h^3 x_d''' / 12
  // its velocity carries h^3 x_d'''' / 12 = h^3 omega^2 x_d'' / 12, counted as the position error it stands for
  // (divided by omega), so that the entry does not swing with the mode's phase (T12c).
  const double moving = end.peak_speed > 0 ? model.length_scale() / end.peak_speed
                                           : (end.peak_spin > 0 ? 1.0 / end.peak_spin : 0.0);
  const double horizon = std::max(end.t - model.initial_state().t, moving);
  auto discounted = [&](const Vec3& whole, const Vec3& deformed, const Vec3& deformed_acceleration, double damping,
                        double peak) {
    const double omega_squared = peak > 0 ? deformed.norm() / peak : 0.0;
    const double decays = std::max(1.0, 0.5 * damping * omega_squared * horizon);
    const double position = (whole - deformed + deformed / decays).norm();
    return std::hypot(position, std::sqrt(omega_squared) * deformed_acceleration.norm() / decays);
  };
  // A beam's nodes come in a row: its rigid motion is found once for them.
  int rigid_beam = -1;
  std::optional<BeamRigidMotion> rigid;
  for (int k = 0; k < model.num_nodes(); ++k) {
    const NodeState& n = end.nodes[k];
    const Vec3 translation = third_derivative(n.mean_v[0], n.mean_v[1], n.mean_v[2]);
    const Vec3 rotation = third_derivative(n.mean_w[0], n.mean_w[1], n.mean_w[2]);
    const int beam = model.beam_of_node(k);
    const double damping = beam >= 0 ? model.beams()[beam].damping : 0.0;
    if (damping > 0) {
      if (beam != rigid_beam) rigid.emplace(model.beams()[beam], end, h);
      rigid_beam = beam;
      const Vec3 deformed_translation = third_derivative(
          rigid->DeformationRate(n, h, 0), rigid->DeformationRate(n, h, 1), rigid->DeformationRate(n, h, 2));
      const Vec3 deformed_rotation =
          third_derivative(rigid->DeformationSpin(n, 0), rigid->DeformationSpin(n, 1), rigid->DeformationSpin(n, 2));
      const Vec3 translation_acceleration =
          (rigid->DeformationRate(n, h, 0) - rigid->DeformationRate(n, h, 1)) / span_newer;
      const Vec3 rotation_acceleration = (rigid->DeformationSpin(n, 0) - rigid->DeformationSpin(n, 1)) / span_newer;
      add(weight * discounted(translation, deformed_translation, translation_acceleration, damping,
                              rigid->largest_rate),
          position_scale, model.node_unknown(k));
      if (!model.rotation_is_algebraic(k)) {
        add(weight * discounted(rotation, deformed_rotation, rotation_acceleration, damping, rigid->largest_spin),
            rotation_scale, model.node_unknown(k) + 3);
      }
    } else {
      add(weight * translation.norm(), position_scale, model.node_unknown(k));
      if (!model.rotation_is_algebraic(k)) add(weight * rotation.norm(), rotation_scale, model.node_unknown(k) + 3);
    }
  }
  const auto& q = end.mean_qdot;
  for (int k = 0; k < model.num_variables(); ++k) {
    if (model.moves_with_algebraic_rotation(k)) continue;
    add(weight * std::abs(third_derivative(q[0][k], q[1][k], q[2][k])),
        JointErrorScale(solver, h[0], end.peak_joint_rate[k]), model.variable_unknown(k));
  }
  // Element states: the same estimate on their mean rates (the midpoint rule's local error is h^3 |x'''| / 24,
  // so the trapezoidal weight errs on the safe side), against the element's own scale.
  const auto& x = end.mean_state_rate;
  for (const auto& element : model.elements()) {
    for (int j = 0; j < element->num_states(); ++j) {
      const int k = element->first_state() + j;
      const double scale = kDefaultFloorFraction * rtol * element->StateScale(j) + rtol * h[0] * end.peak_state_rate[k];
      add(weight * std::abs(third_derivative(x[0][k], x[1][k], x[2][k])), scale, model.element_state_unknown(k));
    }
  }
  estimate.error = count > 0 ? std::sqrt(sum / count) : 0.0;
  return estimate;
}

void RecordStepHistory(const State& start, double h, State* end) {
  end->h_prev = h;
  end->history_steps = start.history_steps + 1;
  end->recent_h = {h, start.recent_h[0], start.recent_h[1]};
  for (size_t k = 0; k < end->nodes.size(); ++k) {
    const NodeState& i = start.nodes[k];
    NodeState& f = end->nodes[k];
    f.mean_v = {(f.x - i.x) / h, i.mean_v[0], i.mean_v[1]};
    f.mean_w = {i.R * Log(i.R.transpose() * f.R) / h, i.mean_w[0], i.mean_w[1]};
    end->peak_speed = std::max(end->peak_speed, f.v.norm());
    end->peak_spin = std::max(end->peak_spin, f.w.norm());
  }
  end->mean_qdot = {(end->q - start.q) / h, start.mean_qdot[0], start.mean_qdot[1]};
  for (Eigen::VectorXd& rates : end->mean_qdot) {
    if (rates.size() != end->q.size()) rates = Eigen::VectorXd::Zero(end->q.size());
  }
  end->mean_state_rate = {(end->element_states - start.element_states) / h, start.mean_state_rate[0],
                          start.mean_state_rate[1]};
  for (Eigen::VectorXd& rates : end->mean_state_rate) {
    if (rates.size() != end->element_states.size()) rates = Eigen::VectorXd::Zero(end->element_states.size());
  }
  if (end->element_states.size() > 0) {
    end->peak_state_rate = end->peak_state_rate.cwiseMax(end->mean_state_rate[0].cwiseAbs());
  }
  if (end->peak_joint_rate.size() != end->qdot.size()) end->peak_joint_rate = Eigen::VectorXd::Zero(end->qdot.size());
  end->peak_joint_rate = end->peak_joint_rate.cwiseMax(end->qdot.cwiseAbs());
}

double NoiseFloor(const Model& model, const State& start) {
  // Bodies that travel beyond the model's initial extent (a fast screw's nut) carry the round-off of where they are.
  double magnitude = model.length_scale();
  if (start.q.size() > 0) magnitude = std::max(magnitude, start.q.cwiseAbs().maxCoeff());
  for (const NodeState& node : start.nodes) magnitude = std::max(magnitude, node.x.cwiseAbs().maxCoeff());
  return RoundOffFloor(magnitude);
}

Eigen::VectorXd CoastingIncrements(const Model& model, const State& start, double h) {
  Eigen::VectorXd x(model.num_unknowns() - model.num_multipliers());
  for (int k = 0; k < model.num_nodes(); ++k) {
    x.segment<3>(model.node_unknown(k)) = h * start.nodes[k].v;
    x.segment<3>(model.node_unknown(k) + 3) = h * start.nodes[k].w;
  }
  for (int k = 0; k < model.num_variables(); ++k) x[model.variable_unknown(k)] = h * start.qdot[k];
  for (int k = 0; k < model.num_element_states(); ++k) {
    x[model.element_state_unknown(k)] = h * start.element_state_rates[k];
  }
  return x;
}

}  // namespace flexmbd
