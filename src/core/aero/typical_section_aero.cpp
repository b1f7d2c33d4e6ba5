// Typical-section aerodynamic element (docs/theory.md, (A6)).

#include "flexmbd/aero/typical_section_aero.hpp"

#include <cmath>

#include "flexmbd/common/error.hpp"

namespace flexmbd {
namespace {
// Local unknowns: 9 node-rate columns (plunge body translation, pitch and flap body rotations), the three joint
// variables, then the inflow states.
constexpr int kNodeColumns = 9, kFirstVariable = 9, kFirstState = 12;
}  // namespace

TypicalSectionAero::TypicalSectionAero(const AeroSectionSpec& spec, const int node_unknowns[3],
                                       const Coordinate coordinates[3], int first_state_unknown)
    : name_(spec.name),
      loads_(spec.semichord, spec.a, spec.c),
      inflow_(spec.inflow_states),
      velocity_(spec.velocity),
      density_(spec.density),
      span_(spec.span) {
  FLEXMBD_DEMAND(spec.inflow_states >= 0 && spec.inflow_states <= kMaxInflowStates);
  for (int k = 0; k < 3; ++k) unknowns_.push_back(node_unknowns[0] + k);      // plunge body translation
  for (int k = 0; k < 3; ++k) unknowns_.push_back(node_unknowns[1] + 3 + k);  // pitch body rotation
  for (int k = 0; k < 3; ++k) unknowns_.push_back(node_unknowns[2] + 3 + k);  // flap body rotation
  for (int k = 0; k < 3; ++k) {
    coordinates_[k] = coordinates[k];
    unknowns_.push_back(coordinates[k].variable_unknown);
    rates_.row(k) = coordinates[k].rate.transpose();
  }
  for (int k = 0; k < spec.inflow_states; ++k) unknowns_.push_back(first_state_unknown + k);
  if (spec.inflow_states > 0) {
    lag_ = inflow_.A.partialPivLu().solve(inflow_.c);
    lag0_ = 0.5 * inflow_.b.dot(lag_);
  }
}

double TypicalSectionAero::Lambda0(const Motion& m) const {
  return num_states() > 0 ? 0.5 * inflow_.b.dot(m.lambda) + lag0_ * loads_.ew.dot(m.qd) : 0.0;
}

void TypicalSectionAero::RateFactors(const StepContext& ctx, double* rate, double* acceleration) const {
  // Mid-step forces read the mean of the end rates and the mean acceleration (v_f - v_i)/h; end-point forces the
  // end values themselves (which AddSchemeRateTerms differentiates as accelerations).
  const bool mid = ctx.mode == AnalysisMode::kDynamic;
  *rate = mid ? 0.5 : 1.0;
  *acceleration = mid ? 1.0 / ctx.h : 0.0;
}

TypicalSectionAero::Motion TypicalSectionAero::Evaluate(const StepContext& ctx) const {
  Eigen::Matrix<double, 9, 1> u = Eigen::Matrix<double, 9, 1>::Zero(), ud = u;
  const int nodes[3] = {unknowns_[0] / 6, unknowns_[3] / 6, unknowns_[6] / 6};
  if (ctx.mode != AnalysisMode::kStatic) {
    const NodeStep& p = (*ctx.nodes)[nodes[0]];
    const NodeStep& a = (*ctx.nodes)[nodes[1]];
    const NodeStep& f = (*ctx.nodes)[nodes[2]];
    if (ctx.mode == AnalysisMode::kDynamic) {
      u << 0.5 * (p.v_i + p.v_f), 0.5 * (a.w_i + a.w_f), 0.5 * (f.w_i + f.w_f);
      ud << (p.v_f - p.v_i) / ctx.h, (a.w_f - a.w_i) / ctx.h, (f.w_f - f.w_i) / ctx.h;
    } else {
      u << p.v_f, a.w_f, f.w_f;
      ud << p.vdot_f, a.wdot_f, f.wdot_f;
    }
  }
  Motion m;
  for (int k = 0; k < 3; ++k) {
    const VariableStep& v = (*ctx.variables)[coordinates_[k].variable];
    m.q[k] = coordinates_[k].sign * (ctx.at_end() ? v.q_f : 0.5 * (v.q_i + v.q_f));
  }
  m.qd = rates_ * u;
  m.qdd = rates_ * ud;
  const int n = num_states();
  m.lambda.resize(n);
  m.lambda_rate.resize(n);
  for (int k = 0; k < n; ++k) {
    const ElementStateStep& x = (*ctx.element_states)[first_state() + k];
    m.lambda[k] = x.value;
    m.lambda_rate[k] = x.rate;
  }
  return m;
}

void TypicalSectionAero::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                     Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const Motion m = Evaluate(ctx);
  const Vec3 Q = GeneralisedForces(m);
  for (int k = 0; k < 3; ++k) {
    r[kFirstVariable + k] -= coordinates_[k].sign * Q[k];
    magnitude[kFirstVariable + k] += std::abs(Q[k]);
  }
  // Peters' inflow (A1) in the states mu = lambda - Abar^-1 cbar ew^T q' (A6):
  // Abar mu' + (U/b) mu - [cbar U eg - (U/b) Abar^-1 cbar ew]^T q' = 0.
  const double decay_rate = velocity_ / loads_.semichord;
  const double slope = velocity_ * loads_.eg.dot(m.qd), rate = decay_rate * loads_.ew.dot(m.qd);
  for (int i = 0; i < num_states(); ++i) {
    const double lag = inflow_.A.row(i).dot(m.lambda_rate), decay = decay_rate * m.lambda[i];
    const double forcing = inflow_.c[i] * slope - lag_[i] * rate;
    r[kFirstState + i] += lag + decay - forcing;
    magnitude[kFirstState + i] += std::abs(lag) + std::abs(decay) + std::abs(forcing);
  }
}

void TypicalSectionAero::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  const double mid = ctx.mid_rate(), U = velocity_, rho = density_, b = loads_.semichord;
  const double circulation = 2.0 * M_PI * rho * U * b;
  // dQ/dq and dQ/dlambda, rates held.
  const Mat3 dQdq = -span_ * (rho * U * U * loads_.Knc + circulation * U * loads_.es * loads_.eg.transpose());
  for (int k = 0; k < 3; ++k) {
    for (int j = 0; j < 3; ++j) {
      J(kFirstVariable + k, kFirstVariable + j) -=
          mid * coordinates_[k].sign * dQdq(k, j) * coordinates_[j].sign;
    }
    for (int n = 0; n < num_states(); ++n) {
      J(kFirstVariable + k, kFirstState + n) -= mid * coordinates_[k].sign * span_ * circulation * loads_.ef[k] * 0.5 *
                                                inflow_.b[n];
    }
  }
  for (int i = 0; i < num_states(); ++i) J(kFirstState + i, kFirstState + i) += mid * U / b;
}

void TypicalSectionAero::AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                                      Eigen::Ref<Eigen::MatrixXd> M) const {
  const double U = velocity_, rho = density_, b = loads_.semichord;
  const double circulation = 2.0 * M_PI * rho * U * b;
  const Mat3 dQdqd =
      -span_ * (rho * U * loads_.Cnc + circulation * (loads_.es - lag0_ * loads_.ef) * loads_.ew.transpose());
  const Mat3 dQdqdd = -span_ * rho * loads_.Ma;
  double rate = 0, acceleration = 0;
  RateFactors(ctx, &rate, &acceleration);
  // Columns of the node rates: through q' = rates_ u and q'' = rates_ u' (or the mean acceleration).
  const Eigen::Matrix<double, 3, 9> dQdu = dQdqd * rates_, dQdud = dQdqdd * rates_;
  const Eigen::Matrix<double, 1, 9> slope = -U * loads_.eg.transpose() * rates_;
  const Eigen::Matrix<double, 1, 9> decay = U / b * loads_.ew.transpose() * rates_;
  Eigen::Ref<Eigen::MatrixXd> acceleration_part = ctx.mode == AnalysisMode::kDynamic ? D : M;
  const double acceleration_factor = ctx.mode == AnalysisMode::kDynamic ? acceleration : 1.0;
  for (int k = 0; k < 3; ++k) {
    const double s = coordinates_[k].sign;
    D.block<1, kNodeColumns>(kFirstVariable + k, 0) -= s * rate * dQdu.row(k);
    acceleration_part.block<1, kNodeColumns>(kFirstVariable + k, 0) -= s * acceleration_factor * dQdud.row(k);
  }
  for (int i = 0; i < num_states(); ++i) {
    D.block<1, kNodeColumns>(kFirstState + i, 0) += rate * (inflow_.c[i] * slope + lag_[i] * decay);
    for (int j = 0; j < num_states(); ++j) D(kFirstState + i, kFirstState + j) += inflow_.A(i, j);
  }
}

void TypicalSectionAero::AddStepWork(const StepContext& ctx, StepWork* work) const {
  if (ctx.mode != AnalysisMode::kDynamic) return;
  const Vec3 Q = GeneralisedForces(Evaluate(ctx));
  for (int k = 0; k < 3; ++k) {
    const VariableStep& v = (*ctx.variables)[coordinates_[k].variable];
    work->external += Q[k] * coordinates_[k].sign * (v.q_f - v.q_i);  // Q_k on q_k = sign (q_f - q_i)
  }
}

Vec3 TypicalSectionAero::GeneralisedForces(const Motion& m) const {
  return span_ * loads_.Forces(density_, velocity_, m.q, m.qd, m.qdd, Lambda0(m));
}

Vec3 TypicalSectionAero::SectionLoads(const StepContext& ctx) const {
  Vec3 Q = GeneralisedForces(Evaluate(ctx));
  Q[0] = -Q[0];  // h is positive down: its generalised force is minus the lift
  return Q;
}

}  // namespace flexmbd
