#include "flexmbd/solver/energy_decaying_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "flexmbd/model/model.hpp"
#include "flexmbd/solver/joint_rates.hpp"
#include "flexmbd/solver/sparse_system.hpp"

#include "drive_rows.hpp"

namespace flexmbd {
namespace {
// The dissipation of one node's translation or rotation over a step is alpha (dv - h a_prev) . M dv (M the
// node's mass, or its inertia tensor for rotations): it is used only where that product is >= 0, judged with
// the previous step's values beforehand and checked after convergence. A product within Newton's tolerance `tol` of
// the two changes' sizes counts as >= 0: on a steady spin the turned lag (T3b) matches the change, the product's sign
// is the solve's error, and deciding it node by node broke a symmetric rotor's symmetry (RotorInflow, hover).
bool Dissipates(const Vec3& dv, const Vec3& dv_lagged, const Mat3& M, double tol) {
  return (dv - dv_lagged).dot(M * dv) >= -tol * (dv.dot(M * dv) + dv_lagged.dot(M * dv_lagged));
}

// Smallest acceleration a step's change of motion is judged against [m/s^2 or rad/s^2]: a step that coasts
// still converges to a velocity error of tol times this per unit time.
constexpr double kAccelerationFloor = 1.0e-6;

// A step that judges its dissipation terms early (DissipationJudging) judges them on an iterate converged to this
// relative tolerance, and the solve then goes on to the full tolerance with the terms kept; the check after
// convergence still drops any that would gain energy. Judged only at full convergence, nearly every step of a
// beam model was solved twice to the full tolerance (200 s flexible antenna: 30,847 Newton iterations and 4,497
// fresh tangents, against 26,761 and 3,733 judged early at 1e-3; at 1e-2 and 1e-4: 25,492 and 27,528 iterations).
// Not tighter: nearly every judging drops some node terms, and the full solve after it then contracts at about
// 0.06 from any start, so the iterations spent judging closer are lost (docs/theory.md, "Newton iteration").
constexpr double kDissipationJudgedAt = 1.0e-2;

// Mode revisions allowed in one step before it is redone shorter (a stop touched and left within the step).
constexpr int kMaxModeRevisions = 4;
constexpr double kModeChatterShrink = 0.25;

// A step shorter than this fraction of the step before that is redone for a friction event is redone from its start
// velocities projected onto the constraints ("Velocity projection after jumps"): the end rates of the longer step
// carry its alternating velocity mode, which the short step has to turn around with constraint forces of the order
// of that step's impulse over its own size, and the slip reversal it saw in its end rates may be that mode's.
constexpr double kShortStepFraction = 0.1;

bool SameModes(const std::vector<EffectState>& a, const std::vector<EffectState>& b) {
  for (size_t k = 0; k < a.size(); ++k) {
    if (a[k].mode != b[k].mode) return false;
  }
  return true;
}
}  // namespace

double DissipationFromRhoInf(double rho_inf) {
  // Unresolved-mode limit of (T3)-(T4): rho (1 - rho) = 2 alpha (1 + rho)^2 (docs/theory.md).
  return rho_inf * (1.0 - rho_inf) / (2.0 * (1.0 + rho_inf) * (1.0 + rho_inf));
}

EnergyDecayingIntegrator::EnergyDecayingIntegrator(const Model& model, SparseSystem* system)
    : model_(model),
      system_(system),
      builder_(model),
      projection_(model, system),
      redundancy_(model),
      alpha_inf_(model.solver().integrator == SolverSpec::Integrator::kEnergyDecaying
                     ? DissipationFromRhoInf(model.solver().rho_inf)
                     : 0.0),
      held_(model.modal_effects().size(), false),
      node_inertia_(model.num_nodes(), Mat3::Identity()),
      elements_all_on_(model.elements().size(), 0.0),
      elements_dissipated_(model.elements().size(), true) {
  for (const RigidBody* body : model.rigid_bodies()) node_inertia_[body->node()] = body->inertia();
  for (const auto& element : model.elements()) {
    if (element->history_size() > 0) elements_all_on_[element->index()] = alpha_inf_;
  }
}

bool EnergyDecayingIntegrator::Coefficients::any() const {
  const auto nonzero = [](double alpha) { return alpha != 0.0; };
  return std::any_of(variables.begin(), variables.end(), nonzero) ||
         std::any_of(elements.begin(), elements.end(), nonzero) ||
         std::any_of(nodes.begin(), nodes.end(), [](const NodeSchemeCoefficients& c) {
           return c.alpha_translation != 0.0 || c.alpha_rotation != 0.0;
         });
}

EnergyDecayingIntegrator::Coefficients EnergyDecayingIntegrator::Choose(const State& start, bool dissipation) const {
  Coefficients c;
  c.nodes.resize(model_.num_nodes());
  c.variables.assign(model_.num_variables(), 0.0);
  c.elements.assign(model_.elements().size(), 0.0);
  if (!dissipation || alpha_inf_ == 0.0 || start.history_steps < 1) return c;
  // Elements with a stretch of their own (beams) start with it on where it dissipated over the last converged
  // step, as the nodes below (their rule is the previous step's check); the check after convergence turns it
  // off where it would gain energy.
  for (const auto& element : model_.elements()) {
    if (elements_dissipated_[element->index()]) c.elements[element->index()] = elements_all_on_[element->index()];
  }
  const double ratio = start.history_steps >= 2 ? 1.0 : 0.0;  // no a_prev2 before the second step
  const double tol = model_.solver().tol;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    c.nodes[k].alpha_translation = Dissipates(n.a_prev, ratio * n.a_prev2, Mat3::Identity(), tol) ? alpha_inf_ : 0.0;
    c.nodes[k].alpha_rotation =
        Dissipates(n.alpha_prev, ratio * n.alpha_prev2, node_inertia_[k], tol) ? alpha_inf_ : 0.0;
  }
  if (start.qddot_prev2.size() != model_.num_variables()) return c;
  for (int k = 0; k < model_.num_variables(); ++k) {
    const double a = start.qddot_prev[k], a_before = start.qddot_prev2[k];
    c.variables[k] = (a - a_before) * a >= 0.0 ? alpha_inf_ : 0.0;
  }
  return c;
}

bool EnergyDecayingIntegrator::DropEnergyGainingDissipation(const State& start, double h, Coefficients* c) const {
  const StepContext& ctx = builder_.context();
  bool dropped = false;
  auto drop_unless = [&dropped](bool dissipates, double* alpha) {
    if (*alpha > 0 && !dissipates) {
      *alpha = 0;
      dropped = true;
    }
  };
  const double tol = model_.solver().tol;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeStep& s = (*ctx.nodes)[k];
    const NodeState& n = start.nodes[k];
    drop_unless(Dissipates(s.v_f - s.v_i, h * n.a_prev, Mat3::Identity(), tol), &c->nodes[k].alpha_translation);
    drop_unless(Dissipates(s.w_f - s.w_i, h * n.alpha_prev, node_inertia_[k], tol), &c->nodes[k].alpha_rotation);
  }
  for (int k = 0; k < model_.num_variables(); ++k) {
    const VariableStep& v = (*ctx.variables)[k];
    const double dq = v.q_f - v.q_i;
    drop_unless((dq - v.dq_lagged) * dq >= 0.0, &c->variables[k]);
  }
  for (const auto& element : model_.elements()) {
    if (c->elements[element->index()] == 0) continue;
    StepWork work;
    element->AddStepWork(ctx, &work);
    drop_unless(work.numerical >= 0.0, &c->elements[element->index()]);
  }
  return dropped;
}

void EnergyDecayingIntegrator::RecordElementDissipation(const Coefficients& c) {
  // The sign of an element's term does not depend on its coefficient: every such element is judged with it on.
  builder_.set_element_dissipation(elements_all_on_);
  for (const auto& element : model_.elements()) {
    if (element->history_size() == 0) continue;
    StepWork work;
    element->AddStepWork(builder_.context(), &work);
    elements_dissipated_[element->index()] = work.numerical >= 0.0;
  }
  builder_.set_element_dissipation(c.elements);
}

Eigen::VectorXd EnergyDecayingIntegrator::Predict(const State& start, double h) const {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(model_.num_unknowns());
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeState& n = start.nodes[k];
    x.segment<3>(model_.node_unknown(k)) = h * n.v + 0.5 * h * h * n.a_prev;
    x.segment<3>(model_.node_unknown(k) + 3) = h * n.w + 0.5 * h * h * n.alpha_prev;
  }
  const bool has_rates = start.qddot_prev.size() == model_.num_variables();
  for (int k = 0; k < model_.num_variables(); ++k) {
    x[model_.variable_unknown(k)] = h * start.qdot[k] + (has_rates ? 0.5 * h * h * start.qddot_prev[k] : 0.0);
  }
  for (int k = 0; k < model_.num_element_states(); ++k) {
    x[model_.element_state_unknown(k)] = h * start.element_state_rates[k];
  }
  x.tail(model_.num_multipliers()) = start.lambda;
  return x;
}

bool EnergyDecayingIntegrator::ReviseModes() {
  bool revised = false;
  for (const ModalEffect* effect : model_.modal_effects()) {
    const int mode = effect->ReviseMode(builder_.context());
    revised = revised || mode != modes_[effect->slot()].mode;
    modes_[effect->slot()].mode = mode;
  }
  return revised;
}

double EnergyDecayingIntegrator::ExpectedJudgingContraction() const {
  // The rate the last judging solve measured, raised to 0.8 so that a rate measured on a lucky pair of
  // increments does not hold for long (Hairer and Wanner, Solving ODEs II, IV.8; RADAU5's FACCON), and at least
  // round-off.
  return std::pow(std::max(judging_contraction_factor_, std::numeric_limits<double>::epsilon()), 0.8);
}

StepResult EnergyDecayingIntegrator::Step(const State& given, double h, State* end) {
  return StepFrom(given, h, end, true);
}

StepResult EnergyDecayingIntegrator::TrialStep(const State& given, double h, State* end) {
  return StepFrom(given, h, end, false);
}

StepResult EnergyDecayingIntegrator::StepFrom(const State& given, double h, State* end, bool dissipation) {
  const State& start = StartOf(given, h);
  started_projected_ = &start == &projected_start_;
  const StepResult result = SolveStep(start, h, end, dissipation);
  if (result.status == StepStatus::kRejectedEvent && end_rate_event_ && h < kShortStepFraction * given.h_prev) {
    short_event_start_ = given.t;
  }
  return result;
}

const State& EnergyDecayingIntegrator::StartOf(const State& given, double h) {
  const Eigen::VectorXd rates = DriveRates(model_, given, RateSide::kAfter);
  if (rates != given.drive_rates) {
    // A drive's rate jumps here: the step starts from the velocities carried across the jump, and the accelerations
    // before it say nothing about the motion after (docs/theory.md, "Jumps of a drive's rate").
    projected_start_ = given;
    if (!projection_.ApplyAtDriveJump(&projected_start_, given.drive_rates, rates, h)) return given;
    projected_start_.history_steps = 0;
    return projected_start_;
  }
  if (given.t != short_event_start_) return given;
  projected_start_ = given;
  const std::vector<bool> nothing_held(held_.size(), false);
  return projection_.Apply(&projected_start_, nothing_held) ? projected_start_ : given;
}

StepResult EnergyDecayingIntegrator::SolveStep(const State& start, double h, State* end, bool dissipation) {
  end_rate_event_ = false;
  Coefficients coefficients = Choose(start, dissipation);
  modes_ = start.effects;
  redundancy_.Mark(start, &modes_);
  builder_.set_effect_modes(&modes_);
  const int n_kinematic = model_.num_unknowns() - model_.num_multipliers();
  StepResult result;
  // A step redone with revised dissipation or modes starts from the last converged solution, which differs from
  // the new one only by what the revision changes.
  Eigen::VectorXd unknowns = Predict(start, h);
  // Newton judges its increments against what the dynamics add to the coasting motion h v_i over the step: a
  // velocity error of tol h |a| per step, an error per unit time whatever the step (docs/theory.md, "Newton
  // iteration").
  const Eigen::VectorXd coasting = CoastingIncrements(model_, start, h);
  int mode_revisions = 0;
  // A step redone for its dissipation or modes costs the iterations of every solve: they are all counted.
  int iterations = 0, fresh_tangents = 0;
  const bool choice_matters = coefficients.any() && model_.solver().tol < kDissipationJudgedAt;
  const bool early = judging_.Early();
  bool judging_dissipation = choice_matters && early;
  // The first solve may start from the previous step's factorisation where the model's steps have shown that it
  // holds (TangentReuse); a solve redone within the step reuses this step's own.
  const bool earlier_tangent = system_->factorisation_key() == h && tangent_reuse_.Attempt();
  bool first_solve = true;
  while (true) {
    int tangents = 0;
    const double tol = judging_dissipation ? kDissipationJudgedAt : model_.solver().tol;
    result.newton = SolveNewton(
        model_, system_, tol, model_.solver().max_iterations, NoiseFloor(model_, start),
        [&](int, bool with_tangent) -> const StepContext& {
          // The first tangent assembled in a step leaves out the geometric stiffness of constraint forces and
          // loads (O(h^2) against inertia) and of beam section forces (spurious at the predictor); one
          // assembled because that one converged slowly includes it.
          tangents += with_tangent ? 1 : 0;
          builder_.set_geometric_stiffness(with_tangent && tangents > 1);
          builder_.set_variable_dissipation(coefficients.variables);
          builder_.set_element_dissipation(coefficients.elements);
          return builder_.Dynamic(start, unknowns, h, coefficients.nodes);
        },
        [&](const Eigen::VectorXd& increment) {
          unknowns += increment;
          return (unknowns.head(n_kinematic) - coasting).cwiseAbs().maxCoeff() + h * h * kAccelerationFloor;
        },
        NewtonOptions{first_solve ? earlier_tangent : system_->factorisation_key() == h, judging_dissipation,
                      judging_dissipation ? ExpectedJudgingContraction() : std::numeric_limits<double>::quiet_NaN()});
    if (judging_dissipation) {
      // A solve that stopped on the expectation measured no rate: the expectation ages by the same power at each
      // use until a solve measures the rate again (NaN stays NaN).
      judging_contraction_factor_ = std::isfinite(result.newton.contraction_factor)
                                        ? result.newton.contraction_factor
                                        : std::pow(judging_contraction_factor_, 0.8);
    }
    if (first_solve && earlier_tangent) tangent_reuse_.Record(result.newton.converged && result.newton.tangents == 0);
    first_solve = false;
    iterations += result.newton.iterations;
    fresh_tangents += result.newton.tangents;
    result.newton.iterations = iterations;
    result.newton.tangents = fresh_tangents;
    // The factorisation now belongs to a step of this size, and may serve the next one of the same size.
    system_->set_factorisation_key(result.newton.converged ? h : std::numeric_limits<double>::quiet_NaN());
    if (result.newton.singular) {
      result.status = StepStatus::kSingularMatrix;
      return result;
    }
    if (!result.newton.converged) {
      result.status = StepStatus::kNewtonDiverged;
      return result;
    }
    builder_.set_variable_dissipation(coefficients.variables);
    builder_.set_element_dissipation(coefficients.elements);
    builder_.Dynamic(start, unknowns, h, coefficients.nodes);
    if (judging_dissipation) {
      judging_dissipation = false;
      DropEnergyGainingDissipation(start, h, &coefficients);
      continue;
    }
    if (DropEnergyGainingDissipation(start, h, &coefficients)) continue;
    if (!ReviseModes()) break;
    redundancy_.Mark(start, &modes_);
    // The factorisation belongs to the old modes.
    system_->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());
    if (++mode_revisions > kMaxModeRevisions) {
      result.status = StepStatus::kRejectedEvent;
      result.limit.retry = kModeChatterShrink * h;
      return result;
    }
  }
  if (choice_matters) judging_.Record(early, iterations);
  if (alpha_inf_ != 0.0 && start.history_steps >= 1) RecordElementDissipation(coefficients);
  Commit(start, unknowns, h, coefficients.nodes, end);
  end_rate_event_ = CommitEffects(end, &result.limit);
  // The accelerations of a step whose modes changed with a jump (an impact, a stick-slip transition) say nothing
  // about the next: the local error estimate and the scheme's dissipation restart their history.
  const bool jumped = ModesJumped(start, *end);
  if (jumped) end->history_steps = 0;
  result.error = EstimateLocalError(model_, *end);
  const bool too_large = model_.solver().adaptive && result.error.error > 1.0;
  result.status = too_large ? StepStatus::kRejectedError : StepStatus::kAccepted;
  if (result.limit.retry < h) result.status = StepStatus::kRejectedEvent;
  // Only a step that stands is worth its projection (two solves).
  if (result.status != StepStatus::kAccepted) return result;
  // A contact brought to rest is held in the projection; a rate that moves a joint less than its error floor over
  // the step is rest already.
  const double negligible_rate = JointErrorFloor(model_.solver()) / h;
  bool comes_to_rest = false;
  for (const ModalEffect* effect : model_.modal_effects()) {
    held_[effect->slot()] = effect->ComesToRest(start, *end, negligible_rate);
    comes_to_rest = comes_to_rest || held_[effect->slot()];
  }
  if ((jumped || comes_to_rest) && projection_.Apply(end, held_)) {
    for (const ModalEffect* effect : model_.modal_effects()) {
      if (held_[effect->slot()]) end->effects[effect->slot()].held_at_rest = true;
    }
  }
  return result;
}

bool EnergyDecayingIntegrator::ModesJumped(const State& start, const State& end) const {
  for (const ModalEffect* effect : model_.modal_effects()) {
    const int k = effect->slot();
    if (start.effects[k].mode != end.effects[k].mode && !effect->ModeChangesAreSmooth()) return true;
  }
  return false;
}

bool EnergyDecayingIntegrator::CommitEffects(State* end, StepLimit* limit) const {
  const StepContext& ctx = builder_.context();
  bool end_rate_event = false;
  for (const ModalEffect* effect : model_.modal_effects()) {
    const StepLimit own = effect->Limit(ctx, *end);
    end_rate_event = end_rate_event || (effect->LocatesEventsFromEndRates() && own.retry < ctx.h);
    limit->Merge(own);
  }
  end->effects = modes_;
  for (const ModalEffect* effect : model_.modal_effects()) {
    EffectState& own = end->effects[effect->slot()];
    effect->Commit(ctx, *end, &own);
    // Held at rest by a projection in the mode it has kept since: a mode left ends it.
    if (own.mode != ctx.start->effects[effect->slot()].mode) own.held_at_rest = false;
  }
  if (!SameModes(modes_, end->effects)) system_->set_factorisation_key(std::numeric_limits<double>::quiet_NaN());
  return end_rate_event;
}

void EnergyDecayingIntegrator::Commit(const State& start, const Eigen::VectorXd& unknowns, double h,
                        const std::vector<NodeSchemeCoefficients>& coefficients, State* end) {
  const StepContext& ctx = builder_.context();
  *end = start;
  end->t = start.t + h;
  for (int k = 0; k < model_.num_nodes(); ++k) {
    const NodeStep& s = (*ctx.nodes)[k];
    NodeState& n = end->nodes[k];
    n.x = s.x_f;
    n.R = s.R_f;
    n.v = s.v_f;
    n.w = s.w_f;
    // The lags of the next step (T3b): this step's mean acceleration, and the one before for the choice of alpha,
    // turned with the node through the step, so that a node carried round a steady spin lags its own change of
    // velocity (docs/theory.md, "A steady spin: the lag turns with the node").
    const Mat3 turn = s.R_f * s.R_i.transpose();
    n.a_prev2 = turn * start.nodes[k].a_prev;
    n.alpha_prev2 = start.nodes[k].alpha_prev;
    n.a_prev = turn * (s.v_f - s.v_i) / h;
    n.alpha_prev = (s.w_f - s.w_i) / h;
  }
  for (int k = 0; k < model_.num_variables(); ++k) end->q[k] = (*ctx.variables)[k].q_f;
  for (int k = 0; k < model_.num_element_states(); ++k) {
    const ElementStateStep& x = (*ctx.element_states)[k];
    end->element_states[k] = x.x_f;
    end->element_state_rates[k] = x.rate;
  }
  for (const auto& element : model_.elements()) {
    if (element->history_size() > 0) element->RecordHistory(ctx, &end->element_history[element->index()]);
  }
  end->lambda = unknowns.tail(model_.num_multipliers());
  end->qdot = JointRates(model_, *end);
  end->qddot_prev2 = start.qddot_prev;
  end->qddot_prev = (end->qdot - start.qdot) / h;
  end->dq_prev = end->q - start.q;
  RecordStepHistory(start, h, end);
  end->drive_rates = DriveRates(model_, *end, RateSide::kBefore);

  StepWork work;
  for (const auto& element : model_.elements()) element->AddStepWork(ctx, &work);
  double numerical = 0;
  for (const RigidBody* body : model_.rigid_bodies()) {
    const NodeStep& s = (*ctx.nodes)[body->node()];
    const NodeState& n = start.nodes[body->node()];
    const NodeSchemeCoefficients& c = coefficients[body->node()];
    const Vec3 dv = s.v_f - s.v_i, dw = s.w_f - s.w_i;
    numerical += c.alpha_translation * body->mass() * (dv - h * n.a_prev).dot(dv) +
                 c.alpha_rotation * (dw - h * n.alpha_prev).dot(body->inertia() * dw);
  }
  end->external_work += work.external;
  end->dissipated_physical += work.dissipated;
  end->dissipated_numerical += numerical + work.numerical;
}

}  // namespace flexmbd
