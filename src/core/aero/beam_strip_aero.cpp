// A strip of unsteady thin-airfoil loads on a beam node (docs/theory.md, (A7)-(A9)).

#include "flexmbd/aero/beam_strip_aero.hpp"

#include <cmath>

#include "flexmbd/common/error.hpp"
#include "flexmbd/math/rotation_vector_calculus.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace {
// Local unknowns: the node's increment (dx in W, theta in the node frame), then the inflow states.
constexpr int kFirstState = 6;
}  // namespace

BeamStripAero::BeamStripAero(const AeroStripSpec& spec, const AeroFlowSpec& flow, int node, int node_unknown,
                             double length, int first_state_unknown)
    : name_(spec.name),
      node_(node),
      semichord_(spec.semichord),
      a_(spec.a),
      length_(length),
      density_(flow.density),
      chord_(spec.chord_axis),
      normal_(spec.normal_axis),
      pitch_axis_(spec.normal_axis.cross(spec.chord_axis)),
      free_stream_(flow.free_stream),
      gust_(flow.gust),
      gust_scale_(flow.gust_scale),
      inflow_(spec.inflow_states),
      scale_(flow.free_stream.norm()) {
  FLEXMBD_DEMAND(spec.inflow_states >= 0 && spec.inflow_states <= kMaxInflowStates);
  for (int k = 0; k < 6; ++k) unknowns_.push_back(node_unknown + k);
  for (int k = 0; k < spec.inflow_states; ++k) unknowns_.push_back(first_state_unknown + k);
  if (spec.inflow_states > 0) {
    lag_ = inflow_.A.partialPivLu().solve(inflow_.c);
    lag0_ = 0.5 * inflow_.b.dot(lag_);
  }
}

BeamStripAero::Motion BeamStripAero::MotionAt(const StepContext& ctx) const {
  const NodeStep& n = (*ctx.nodes)[node_];
  const double t = ctx.at_end() ? ctx.t_f : 0.5 * (ctx.t_i + ctx.t_f);
  Motion m;
  Vec3 v = Vec3::Zero(), acceleration = Vec3::Zero();
  m.w.setZero();
  m.wdot.setZero();
  if (ctx.mode == AnalysisMode::kDynamic) {
    // Mid-step: the frame halfway through the rotation increment, mean rates, mean accelerations (as the
    // node's inertia reads them, so that the apparent mass acts as mass does in the scheme).
    const RotationVectorCalculus half(0.5 * n.theta, RotationVectorCalculus::Level::kMaps);
    m.R = n.R_i * half.exp();
    m.turn = 0.5 * half.tangent();
    v = 0.5 * (n.v_i + n.v_f);
    acceleration = (n.v_f - n.v_i) / ctx.h;
    m.w = 0.5 * (n.w_i + n.w_f);
    m.wdot = (n.w_f - n.w_i) / ctx.h;
  } else {
    m.R = n.R_f;
    m.turn = Mat3::Identity();
    if (ctx.mode == AnalysisMode::kEndPoint) {
      v = n.v_f;
      acceleration = n.vdot_f;
      m.w = n.w_f;
      m.wdot = n.wdot_f;
    }
  }
  const Vec3 air = free_stream_ + Evaluate(gust_scale_, t) * gust_;
  m.V = m.R.transpose() * (air - v);
  m.Vdot = m.R.transpose() * (EvaluateRate(gust_scale_, t) * gust_ - acceleration);
  const int N = num_states();
  m.mu.resize(N);
  m.mu_rate.resize(N);
  for (int k = 0; k < N; ++k) {
    const ElementStateStep& x = (*ctx.element_states)[first_state() + k];
    m.mu[k] = x.value;
    m.mu_rate[k] = x.rate;
  }
  return m;
}

BeamStripAero::Loads BeamStripAero::Compute(const Motion& m) const {
  const double b = semichord_, a = a_, rho = density_;
  const Vec3 &c = chord_, &n = normal_, &e = pitch_axis_;
  const int N = num_states();
  Loads out;
  // Strip kinematics (A7): chordwise speed, normal velocity and its rate, pitch rate and its rate.
  out.u = c.dot(m.V);
  const double omega = e.dot(m.w), omega_rate = e.dot(m.wdot);
  const Vec3 turning_normal = m.w.cross(n), normal_sweep = n.cross(m.V);
  const double v_rate = turning_normal.dot(m.V) + n.dot(m.Vdot);
  const double arm34 = b * (0.5 - a);  // from the elastic axis to the three-quarter chord
  out.w34 = n.dot(m.V) + arm34 * omega;
  out.du_dV = c.transpose();
  out.dw34_dV = n.transpose();
  out.dw34_dw = arm34 * e.transpose();
  // Circulatory lift (A8): 2 pi rho u b (w34 - lambda0), lambda0 = bbar^T mu / 2 + lag0 w34.
  const double lambda0 = N > 0 ? 0.5 * inflow_.b.dot(m.mu) + lag0_ * out.w34 : 0.0;
  const double k = 2.0 * M_PI * rho * b, downwash = out.w34 - lambda0;
  const double circulation = k * out.u * downwash;
  const Eigen::Matrix<double, 1, 3> dG_dV = k * (downwash * out.du_dV + out.u * (1.0 - lag0_) * out.dw34_dV);
  const Eigen::Matrix<double, 1, 3> dG_dw = k * out.u * (1.0 - lag0_) * out.dw34_dw;
  // Apparent mass and the circulatory lift at the quarter chord, b (1/2 + a) ahead of the elastic axis (A8).
  const double apparent = M_PI * rho * b * b, arm = b * (0.5 + a), inertia = b * b * (0.125 + a * a);
  out.lift = apparent * (v_rate - b * a * omega_rate) + circulation;
  out.moment = apparent * (b * a * v_rate - 0.5 * out.u * b * omega - inertia * omega_rate) + arm * circulation;
  out.dV.row(0) = apparent * turning_normal.transpose() + dG_dV;
  out.dV.row(1) = apparent * (b * a * turning_normal.transpose() - 0.5 * b * omega * c.transpose()) + arm * dG_dV;
  out.dw.row(0) = apparent * normal_sweep.transpose() + dG_dw;
  out.dw.row(1) = apparent * (b * a * normal_sweep.transpose() - 0.5 * out.u * b * e.transpose()) + arm * dG_dw;
  out.dVdot.row(0) = apparent * n.transpose();
  out.dVdot.row(1) = apparent * b * a * n.transpose();
  out.dwdot.row(0) = -apparent * b * a * e.transpose();
  out.dwdot.row(1) = -apparent * inertia * e.transpose();
  out.dmu.resize(2, N);
  for (int j = 0; j < N; ++j) {
    const double dG = -k * out.u * 0.5 * inflow_.b[j];
    out.dmu(0, j) = dG;
    out.dmu(1, j) = arm * dG;
  }
  return out;
}

Vec6 BeamStripAero::NodeForces(const Motion& m, const Loads& loads) const {
  Vec6 q;
  q.head<3>() = length_ * loads.lift * (m.R * normal_);
  q.tail<3>() = length_ * loads.moment * pitch_axis_;
  return q;
}

void BeamStripAero::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const Motion m = MotionAt(ctx);
  const Loads loads = Compute(m);
  const Vec6 q = NodeForces(m, loads);
  r.head<6>() -= q;
  magnitude.head<6>() += q.cwiseAbs();
  // Peters' inflow (A1) in mu = lambda - Abar^-1 cbar w34 (A9): Abar mu' + (u/b)(mu + Abar^-1 cbar w34) = 0.
  const double decay_rate = loads.u / semichord_;
  for (int i = 0; i < num_states(); ++i) {
    const double lag = inflow_.A.row(i).dot(m.mu_rate), decay = decay_rate * (m.mu[i] + lag_[i] * loads.w34);
    r[kFirstState + i] += lag + decay;
    magnitude[kFirstState + i] += std::abs(lag) + std::abs(decay);
  }
}

void BeamStripAero::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  const Motion m = MotionAt(ctx);
  const Loads loads = Compute(m);
  const double mid = ctx.mid_rate(), b = semichord_;
  // The section frame turns with the rotation increment: V = R^T (air - v) and Vdot turn against it.
  const Mat3 dV = Skew(m.V) * m.turn, dVdot = Skew(m.Vdot) * m.turn;
  const Eigen::Matrix<double, 2, 3> dloads = loads.dV * dV + loads.dVdot * dVdot;
  const Vec3 normal_W = m.R * normal_;
  J.block<3, 3>(0, 3) -= length_ * (normal_W * dloads.row(0) - loads.lift * m.R * Skew(normal_) * m.turn);
  J.block<3, 3>(3, 3) -= length_ * pitch_axis_ * dloads.row(1);
  const int N = num_states();
  for (int j = 0; j < N; ++j) {
    J.block<3, 1>(0, kFirstState + j) -= mid * length_ * loads.dmu(0, j) * normal_W;
    J.block<3, 1>(3, kFirstState + j) -= mid * length_ * loads.dmu(1, j) * pitch_axis_;
  }
  for (int i = 0; i < N; ++i) {
    const Eigen::Matrix<double, 1, 3> d_decay =
        ((m.mu[i] + lag_[i] * loads.w34) * loads.du_dV + loads.u * lag_[i] * loads.dw34_dV) / b;
    J.block<1, 3>(kFirstState + i, 3) += d_decay * dV;
    J(kFirstState + i, kFirstState + i) += mid * loads.u / b;
  }
}

void BeamStripAero::AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                                 Eigen::Ref<Eigen::MatrixXd> M) const {
  const Motion m = MotionAt(ctx);
  const Loads loads = Compute(m);
  const bool mid = ctx.mode == AnalysisMode::kDynamic;
  // Mid-step forces read the mean rates and the mean accelerations (v_f - v_i)/h; end-point forces the end
  // rates and accelerations themselves.
  const double rate = mid ? 0.5 : 1.0, acceleration = mid ? 1.0 / ctx.h : 1.0;
  Eigen::Ref<Eigen::MatrixXd> acceleration_part = mid ? D : M;
  const Mat3 Rt = m.R.transpose();
  const Vec3 normal_W = m.R * normal_;
  // Columns: node translation rate (V = R^T (air - v)) and body-frame angular rate.
  const Eigen::Matrix<double, 2, 3> by_v = -loads.dV * Rt, by_a = -loads.dVdot * Rt;
  D.block<3, 3>(0, 0) -= rate * length_ * normal_W * by_v.row(0);
  D.block<3, 3>(3, 0) -= rate * length_ * pitch_axis_ * by_v.row(1);
  D.block<3, 3>(0, 3) -= rate * length_ * normal_W * loads.dw.row(0);
  D.block<3, 3>(3, 3) -= rate * length_ * pitch_axis_ * loads.dw.row(1);
  acceleration_part.block<3, 3>(0, 0) -= acceleration * length_ * normal_W * by_a.row(0);
  acceleration_part.block<3, 3>(3, 0) -= acceleration * length_ * pitch_axis_ * by_a.row(1);
  acceleration_part.block<3, 3>(0, 3) -= acceleration * length_ * normal_W * loads.dwdot.row(0);
  acceleration_part.block<3, 3>(3, 3) -= acceleration * length_ * pitch_axis_ * loads.dwdot.row(1);
  const double b = semichord_;
  for (int i = 0; i < num_states(); ++i) {
    const Eigen::Matrix<double, 1, 3> d_decay =
        ((m.mu[i] + lag_[i] * loads.w34) * loads.du_dV + loads.u * lag_[i] * loads.dw34_dV) / b;
    D.block<1, 3>(kFirstState + i, 0) -= rate * d_decay * Rt;
    D.block<1, 3>(kFirstState + i, 3) += rate * loads.u * lag_[i] / b * loads.dw34_dw;
    for (int j = 0; j < num_states(); ++j) D(kFirstState + i, kFirstState + j) += inflow_.A(i, j);
  }
}

void BeamStripAero::AddStepWork(const StepContext& ctx, StepWork* work) const {
  if (ctx.mode != AnalysisMode::kDynamic) return;
  const Motion m = MotionAt(ctx);
  const Vec6 q = NodeForces(m, Compute(m));
  const NodeStep& n = (*ctx.nodes)[node_];
  work->external += q.head<3>().dot(n.dx) + q.tail<3>().dot(n.theta);
}

Eigen::Vector2d BeamStripAero::StripLoads(const StepContext& ctx) const {
  const Loads loads = Compute(MotionAt(ctx));
  return length_ * Eigen::Vector2d(loads.lift, loads.moment);
}

}  // namespace flexmbd
