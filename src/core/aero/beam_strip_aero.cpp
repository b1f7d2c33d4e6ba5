// A strip of unsteady thin-airfoil loads on a beam node, with its flap if it has one (docs/theory.md, (A7)-(A10)).

#include "flexmbd/aero/beam_strip_aero.hpp"

#include <cmath>

#include "flexmbd/common/error.hpp"
#include "flexmbd/math/rotation_vector_calculus.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace {
// Local unknowns: the node's increment (dx in W, theta in the node frame), the flap node's if there is one, the
// inflow states, then the rotor's inflow if the strip is on a rotor.
constexpr int kRotation = 3, kFlapRotation = 9;
using Row3 = Eigen::Matrix<double, 1, 3>;

// A node's frame where the loads read it, the frame's change per unit rotation increment, its angular velocity
// and acceleration (node frame): mid-step values in a dynamic step (the frame halfway through the increment, mean
// rates, mean accelerations as the node's inertia reads them), end values otherwise.
struct NodeFrame {
  Mat3 R, turn;
  Vec3 w = Vec3::Zero(), wdot = Vec3::Zero();
};
NodeFrame FrameAt(const NodeStep& n, const StepContext& ctx) {
  NodeFrame f;
  if (ctx.mode == AnalysisMode::kDynamic) {
    const RotationVectorCalculus half(0.5 * n.theta, RotationVectorCalculus::Level::kMaps);
    f.R = n.R_i * half.exp();
    f.turn = 0.5 * half.tangent();
    f.w = 0.5 * (n.w_i + n.w_f);
    f.wdot = (n.w_f - n.w_i) / ctx.h;
  } else {
    f.R = n.R_f;
    f.turn = Mat3::Identity();
    if (ctx.mode == AnalysisMode::kEndPoint) {
      f.w = n.w_f;
      f.wdot = n.wdot_f;
    }
  }
  return f;
}
}  // namespace

BeamStripAero::BeamStripAero(const AeroStripSpec& spec, const AeroFlowSpec& flow, int node, int node_unknown,
                             double length, int first_state_unknown, const StripFlap& flap, const StripRotor& rotor)
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
      scale_(flow.free_stream.norm()),
      flap_(flap),
      flap_loads_(spec.semichord, spec.a, spec.flap.c),
      flap_chord_(flap.R_rest * chord_),
      flap_pitch_axis_(flap.R_rest * pitch_axis_),
      rotor_(rotor) {
  FLEXMBD_DEMAND(spec.inflow_states >= 0 && spec.inflow_states <= kMaxInflowStates);
  FLEXMBD_DEMAND(!has_flap() || (flap.fraction > 0.0 && flap.fraction <= 1.0));
  for (int k = 0; k < 6; ++k) unknowns_.push_back(node_unknown + k);
  if (has_flap()) {
    for (int k = 0; k < 6; ++k) unknowns_.push_back(flap.node_unknown + k);
  }
  for (int k = 0; k < spec.inflow_states; ++k) unknowns_.push_back(first_state_unknown + k);
  for (int k = 0; has_rotor() && k < rotor.num_states; ++k) unknowns_.push_back(rotor.unknown + k);
  if (spec.inflow_states > 0) {
    lag_ = inflow_.A.partialPivLu().solve(inflow_.c);
    lag0_ = 0.5 * inflow_.b.dot(lag_);
  }
}

BeamStripAero::Motion BeamStripAero::MotionAt(const StepContext& ctx) const {
  const NodeStep& n = (*ctx.nodes)[node_];
  const double t = ctx.force_time();
  const NodeFrame frame = FrameAt(n, ctx);
  Motion m;
  m.R = frame.R;
  m.turn = frame.turn;
  m.w = frame.w;
  m.wdot = frame.wdot;
  Vec3 v = Vec3::Zero(), acceleration = Vec3::Zero();
  if (ctx.mode == AnalysisMode::kDynamic) {
    v = 0.5 * (n.v_i + n.v_f);
    acceleration = (n.v_f - n.v_i) / ctx.h;
  } else if (ctx.mode == AnalysisMode::kEndPoint) {
    v = n.v_f;
    acceleration = n.vdot_f;
  }
  m.v = v;
  if (has_rotor()) {
    // The inflow at the strip's place in the disc (A14), and its rate along the strip's path.
    const int nr = rotor_.num_states;
    m.rotor_nu.resize(nr);
    m.rotor_nu_rate.resize(nr);
    for (int k = 0; k < nr; ++k) {
      const ElementStateStep& x = (*ctx.element_states)[rotor_.state + k];
      m.rotor_nu[k] = x.value;
      m.rotor_nu_rate[k] = x.rate;
    }
    const Vec3 place = (ctx.mode == AnalysisMode::kDynamic ? 0.5 * (n.x_i + n.x_f) : n.x_f) - rotor_.center;
    const auto gradient = RotorWeightGradient();
    // (1, e_c . p / R, e_s . p / R), the gradient's first column being zero; written as Unit(nr, 0) plus the
    // product, the sum would go through a temporary of unbounded size, on the heap.
    m.weights = gradient.transpose() * place;
    m.weights[0] += 1.0;
    m.nu_gradient = gradient * m.rotor_nu;
    m.nu_rate_gradient = gradient * m.rotor_nu_rate;
    m.nu = m.weights.dot(m.rotor_nu);
    m.nu_rate = m.weights.dot(m.rotor_nu_rate) + v.dot(m.nu_gradient);
  }
  // The rotor's inflow blows along -axis (A13).
  const Vec3 air = free_stream_ + Evaluate(gust_scale_, t) * gust_ - m.nu * rotor_.axis;
  // An equilibrium holds the air as it is at t, at rest: the gust's rate, like the node's, is no load on it.
  const double gust_rate = ctx.mode == AnalysisMode::kStatic ? 0.0 : EvaluateRate(gust_scale_, t);
  m.V = m.R.transpose() * (air - v);
  m.Vdot = m.R.transpose() * (gust_rate * gust_ - m.nu_rate * rotor_.axis - acceleration);
  if (has_flap()) {
    const NodeFrame flap = FrameAt((*ctx.nodes)[flap_.node], ctx);
    m.R_flap = flap.R;
    m.turn_flap = flap.turn;
    m.w_flap = flap.w;
    m.wdot_flap = flap.wdot;
  }
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

BeamStripAero::Flap BeamStripAero::FlapOf(const Motion& m) const {
  Flap f;
  if (!has_flap()) return f;
  // (A10): the flap's chord in the strip's frame, p = R^T R_flap c_flap, makes the angle delta with the chord,
  // trailing edge down (towards -n).
  const Mat3 relative = m.R.transpose() * m.R_flap;
  const Vec3 p = relative * flap_chord_;
  const double along = chord_.dot(p), down = -normal_.dot(p);
  f.delta[0] = std::atan2(down, along);
  // d delta = g . dp, dp = Skew(p) dtheta_frame - relative Skew(c_flap) dtheta_flap_frame.
  const Row3 g = (-down * chord_ - along * normal_).transpose() / (along * along + down * down);
  f.d_node = g * Skew(p) * m.turn;
  f.d_flap = -g * relative * Skew(flap_chord_) * m.turn_flap;
  f.delta[1] = flap_pitch_axis_.dot(m.w_flap) - pitch_axis_.dot(m.w);
  f.delta[2] = flap_pitch_axis_.dot(m.wdot_flap) - pitch_axis_.dot(m.wdot);
  return f;
}

BeamStripAero::Loads BeamStripAero::Compute(const Motion& m, const Flap& f) const {
  const double b = semichord_, a = a_, rho = density_;
  const Vec3 &c = chord_, &n = normal_, &e = pitch_axis_;
  const int N = num_states();
  Loads out;
  out.y.setZero(3 + N);
  out.dV.setZero(3 + N, 3);
  out.dw.setZero(3 + N, 3);
  out.dVdot.setZero(3 + N, 3);
  out.dwdot.setZero(3 + N, 3);
  out.dflap.setZero(3 + N, 3);
  out.dmu.setZero(3 + N, N);
  // Strip kinematics (A7): chordwise speed, normal velocity and its rate, pitch rate and its rate.
  out.u = c.dot(m.V);
  const double omega = e.dot(m.w), omega_rate = e.dot(m.wdot);
  const Vec3 turning_normal = m.w.cross(n), normal_sweep = n.cross(m.V);
  const double v_rate = turning_normal.dot(m.V) + n.dot(m.Vdot);
  // In reverse flow (u < 0, air from the trailing edge) the plate's edges swap roles (A12): the circulation and
  // the wake read the speed |u|, the three-quarter chord and the quarter chord lie mirrored about mid-chord.
  const double flow = out.u < 0.0 ? -1.0 : 1.0, speed = flow * out.u;
  const Row3 dspeed_dV = flow * c.transpose();
  const double arm34 = b * (0.5 * flow - a);  // from the elastic axis to the three-quarter chord, aft
  // The flap's three-quarter-chord downwash (A10) over its share of the strip.
  const double phi = has_flap() ? flap_.fraction : 0.0, ew = flap_loads_.ew[2], eg = flap_loads_.eg[2];
  out.w34 = n.dot(m.V) + arm34 * omega + phi * (ew * f.delta[1] + out.u * eg * f.delta[0]);
  const Row3 du_dV = c.transpose();
  out.dw34_dV = n.transpose() + phi * eg * f.delta[0] * du_dV;
  out.dw34_dw = arm34 * e.transpose();
  out.dw34_dflap = phi * Row3(out.u * eg, ew, 0.0);
  // Circulatory lift (A8): 2 pi rho u b (w34 - lambda0), lambda0 = bbar^T mu / 2 + lag0 w34.
  const double lambda0 = N > 0 ? 0.5 * inflow_.b.dot(m.mu) + lag0_ * out.w34 : 0.0;
  const double k = 2.0 * M_PI * rho * b, downwash = out.w34 - lambda0;
  const double circulation = k * speed * downwash;
  const Row3 dG_dV = k * (downwash * dspeed_dV + speed * (1.0 - lag0_) * out.dw34_dV);
  const Row3 dG_dw = k * speed * (1.0 - lag0_) * out.dw34_dw;
  const Row3 dG_dflap = k * speed * (1.0 - lag0_) * out.dw34_dflap;
  // Apparent mass and the circulatory lift at the quarter chord, b (1/2 + a) ahead of the elastic axis (A8).
  const double apparent = M_PI * rho * b * b, arm = b * (0.5 * flow + a), inertia = b * b * (0.125 + a * a);
  out.y[0] = apparent * (v_rate - b * a * omega_rate) + circulation;
  out.y[1] = apparent * (b * a * v_rate - 0.5 * speed * b * omega - inertia * omega_rate) + arm * circulation;
  out.dV.row(0) = apparent * turning_normal.transpose() + dG_dV;
  out.dV.row(1) = apparent * (b * a * turning_normal.transpose() - 0.5 * b * omega * dspeed_dV) + arm * dG_dV;
  out.dw.row(0) = apparent * normal_sweep.transpose() + dG_dw;
  out.dw.row(1) = apparent * (b * a * normal_sweep.transpose() - 0.5 * speed * b * e.transpose()) + arm * dG_dw;
  out.dVdot.row(0) = apparent * n.transpose();
  out.dVdot.row(1) = apparent * b * a * n.transpose();
  out.dwdot.row(0) = -apparent * b * a * e.transpose();
  out.dwdot.row(1) = -apparent * inertia * e.transpose();
  out.dflap.row(0) = dG_dflap;
  out.dflap.row(1) = arm * dG_dflap;
  for (int j = 0; j < N; ++j) {
    const double dG = -k * speed * 0.5 * inflow_.b[j];
    out.dmu(0, j) = dG;
    out.dmu(1, j) = arm * dG;
  }
  if (has_flap()) AddFlapTerms(m, f, &out);
  // The decay of Peters' inflow (A9): (|u|/b) (mu_i + lag_i w34).
  for (int i = 0; i < N; ++i) {
    const int row = 3 + i;
    out.y[row] = speed / b * (m.mu[i] + lag_[i] * out.w34);
    out.dV.row(row) = ((m.mu[i] + lag_[i] * out.w34) * dspeed_dV + speed * lag_[i] * out.dw34_dV) / b;
    out.dw.row(row) = speed * lag_[i] / b * out.dw34_dw;
    out.dflap.row(row) = speed * lag_[i] / b * out.dw34_dflap;
    out.dmu(row, i) = speed / b;
  }
  return out;
}

void BeamStripAero::AddFlapTerms(const Motion& m, const Flap& f, Loads* out) const {
  const double b = semichord_, rho = density_, k = 2.0 * M_PI * rho * b, u = out->u, phi = flap_.fraction;
  const Mat3 &Ma = flap_loads_.Ma, &Cnc = flap_loads_.Cnc, &Knc = flap_loads_.Knc;
  const Vec3 &c = chord_, &n = normal_, &e = pitch_axis_;
  const Row3 du_dV = c.transpose();
  const double angle = f.delta[0], rate = f.delta[1], acceleration = f.delta[2];
  const double ew = flap_loads_.ew[2], eg = flap_loads_.eg[2];
  const double w34_flap = ew * rate + u * eg * angle;
  const Row3 dflap_w34 = Row3(u * eg, ew, 0.0);
  // The flap column of (A4)'s acyclic terms in row r (r = 0 plunge, 1 pitch) and its gradients.
  auto acyclic = [&](int r, double* value, Row3* by_V, Row3* by_flap) {
    *value = Ma(r, 2) * acceleration + u * Cnc(r, 2) * rate + u * u * Knc(r, 2) * angle;
    *by_V = (Cnc(r, 2) * rate + 2.0 * u * Knc(r, 2) * angle) * du_dV;
    *by_flap = Row3(u * u * Knc(r, 2), u * Cnc(r, 2), Ma(r, 2));
  };
  double value = 0;
  Row3 by_V, by_flap;
  // Lift -Q_h: the circulation already reads the flap's w34.
  acyclic(0, &value, &by_V, &by_flap);
  out->y[0] += phi * rho * value;
  out->dV.row(0) += phi * rho * by_V;
  out->dflap.row(0) += phi * rho * by_flap;
  // Moment Q_alpha: the Kutta loading of the flap's w34 acts at es_alpha = -a b, which is b/2 behind the
  // quarter-chord arm the circulation was given.
  acyclic(1, &value, &by_V, &by_flap);
  out->y[1] -= phi * (rho * value + 0.5 * b * k * u * w34_flap);
  out->dV.row(1) -= phi * (rho * by_V + 0.5 * b * k * (w34_flap + u * eg * angle) * du_dV);
  out->dflap.row(1) -= phi * (rho * by_flap + 0.5 * b * k * u * dflap_w34);
  // Hinge moment Q_delta (A5) in the strip's variables (A10): the rigid columns through v_n, omega and their rates,
  // the flap's own, and the Kutta and wake loadings of the flapped section's w34 = w34 + (1 - phi) w34_flap.
  const double v_n = n.dot(m.V), omega = e.dot(m.w);
  const double v_rate = m.w.cross(n).dot(m.V) + n.dot(m.Vdot), omega_rate = e.dot(m.wdot);
  const double pitch_rate_term = Cnc(2, 1) - Ma(2, 0);
  acyclic(2, &value, &by_V, &by_flap);
  const double rigid = Ma(2, 0) * v_rate + Ma(2, 1) * omega_rate + u * Knc(2, 1) * v_n + u * pitch_rate_term * omega;
  const int N = num_states();
  const double lambda0 = N > 0 ? 0.5 * inflow_.b.dot(m.mu) + lag0_ * out->w34 : 0.0;
  const double f0 = flap_loads_.es[2], f_wake = flap_loads_.ef[2];
  const double Q = out->w34 + (1.0 - phi) * w34_flap, kutta = f0 * Q - f_wake * lambda0;
  out->y[2] = phi * (-rho * (rigid + value) - k * u * kutta);
  const Row3 dQ_dV = out->dw34_dV + (1.0 - phi) * eg * angle * du_dV;
  const Row3 rigid_dV = Ma(2, 0) * m.w.cross(n).transpose() + Knc(2, 1) * (v_n * du_dV + u * n.transpose()) +
                        pitch_rate_term * omega * du_dV;
  out->dV.row(2) =
      -phi * (rho * (rigid_dV + by_V) + k * (kutta * du_dV + u * (f0 * dQ_dV - f_wake * lag0_ * out->dw34_dV)));
  out->dw.row(2) = -phi * (rho * (Ma(2, 0) * n.cross(m.V).transpose() + u * pitch_rate_term * e.transpose()) +
                           k * u * (f0 - f_wake * lag0_) * out->dw34_dw);
  out->dVdot.row(2) = -phi * rho * Ma(2, 0) * n.transpose();
  out->dwdot.row(2) = -phi * rho * Ma(2, 1) * e.transpose();
  out->dflap.row(2) = -phi * (rho * by_flap + k * u * (f0 * (out->dw34_dflap + (1.0 - phi) * dflap_w34) -
                                                     f_wake * lag0_ * out->dw34_dflap));
  for (int j = 0; j < N; ++j) out->dmu(2, j) = phi * k * u * f_wake * 0.5 * inflow_.b[j];
}

Eigen::Matrix<double, 12, 3> BeamStripAero::ForceMap(const Motion& m) const {
  // Lift along the chord normal in W on the node's translation; the moment about the pitch axis on its rotation;
  // the hinge moment on the flap node's rotation and, opposite, on the node's (the conjugate of the flap angle).
  Eigen::Matrix<double, 12, 3> F = Eigen::Matrix<double, 12, 3>::Zero();
  F.block<3, 1>(0, 0) = m.R * normal_;
  F.block<3, 1>(kRotation, 1) = pitch_axis_;
  if (has_flap()) {
    F.block<3, 1>(kRotation, 2) = -pitch_axis_;
    F.block<3, 1>(kFlapRotation, 2) = flap_pitch_axis_;
  }
  return length_ * F;
}

void BeamStripAero::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                                Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const Motion m = MotionAt(ctx);
  const Loads loads = Compute(m, FlapOf(m));
  const int nn = num_node_unknowns();
  // A static solve raises the air's loads with its other loads (theory (A11)); the inflow equations stay whole.
  const Eigen::Matrix<double, 12, 1> q = ctx.load_factor * ForceMap(m) * loads.y.head<3>();
  r.head(nn) -= q.head(nn);
  magnitude.head(nn) += q.head(nn).cwiseAbs();
  // Peters' inflow (A1) in mu = lambda - Abar^-1 cbar w34 (A9): Abar mu' + (u/b)(mu + Abar^-1 cbar w34) = 0.
  for (int i = 0; i < num_states(); ++i) {
    const double lag = inflow_.A.row(i).dot(m.mu_rate), decay = loads.y[3 + i];
    r[nn + i] += lag + decay;
    magnitude[nn + i] += std::abs(lag) + std::abs(decay);
  }
  // The strip's share of the rotor's thrust (and its moments) in the inflow's rows (A13), (A14); an equilibrium
  // keeps the inflow it has.
  if (has_rotor() && ctx.mode != AnalysisMode::kStatic) {
    const RotorStates thrust = ThrustShare(m) * loads.y[0] * m.weights;
    r.segment(rotor_local(), thrust.size()) -= thrust;
    magnitude.segment(rotor_local(), thrust.size()) += thrust.cwiseAbs();
  }
}

void BeamStripAero::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  const Motion m = MotionAt(ctx);
  const Flap f = FlapOf(m);
  const Loads loads = Compute(m, f);
  const Eigen::Matrix<double, 12, 3> F = ctx.load_factor * ForceMap(m);
  const int nn = num_node_unknowns(), N = num_states();
  // The section frame turns with the rotation increment: V = R^T (air - v) and Vdot turn against it; the flap
  // angle turns with both frames.
  const RowGradient by_node =
      loads.dV * (Skew(m.V) * m.turn) + loads.dVdot * (Skew(m.Vdot) * m.turn) + loads.dflap.col(0) * f.d_node;
  J.block(0, kRotation, nn, 3) -= F.topRows(nn) * by_node.topRows<3>();
  // d(R n) = -R Skew(n) dtheta
  J.block<3, 3>(0, kRotation) += ctx.load_factor * length_ * loads.y[0] * m.R * Skew(normal_) * m.turn;
  J.block(nn, kRotation, N, 3) += by_node.bottomRows(N);
  if (has_flap()) {
    const RowGradient by_flap = loads.dflap.col(0) * f.d_flap;
    J.block(0, kFlapRotation, nn, 3) -= F.topRows(nn) * by_flap.topRows<3>();
    J.block(nn, kFlapRotation, N, 3) += by_flap.bottomRows(N);
  }
  const double mid = ctx.mid_rate();
  J.block(0, nn, nn, N) -= mid * F.topRows(nn) * loads.dmu.topRows(3);
  J.block(nn, nn, N, N) += mid * loads.dmu.bottomRows(N);
  if (!has_rotor()) return;
  // The rotor's inflow moves the air along -axis: V changes by -R^T axis per unit nu at the strip, Vdot by as much
  // per unit of its rate. Both read the states through the strip's weights, the rate also through the strip's
  // velocity across the disc's gradient (A14); the strip's place moves both.
  const int ri = rotor_local(), nr = rotor_.num_states;
  const Vec3 down = m.R.transpose() * rotor_.axis;
  const Rows by_nu = -loads.dV * down, by_nu_rate = -loads.dVdot * down;
  const auto gradient = RotorWeightGradient();
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxRows, 3> by_states =
      by_nu * m.weights.transpose() + by_nu_rate * (gradient.transpose() * m.v).transpose();
  const RowGradient by_place = mid * (by_nu * m.nu_gradient.transpose() + by_nu_rate * m.nu_rate_gradient.transpose());
  J.block(0, ri, nn, nr) -= mid * F.topRows(nn) * by_states.topRows(3);
  J.block(nn, ri, N, nr) += mid * by_states.bottomRows(N);
  J.block(0, 0, nn, 3) -= F.topRows(nn) * by_place.topRows<3>();
  J.block(nn, 0, N, 3) += by_place.bottomRows(N);
  if (ctx.mode == AnalysisMode::kStatic) return;
  // The inflow's rows: the lift's gradients times the share along the axis, which turns with the chord normal,
  // times the weights, which move with the strip's place.
  const double share = ThrustShare(m);
  J.block(ri, kRotation, nr, 3) -= m.weights * (share * by_node.row(0));
  J.block(ri, kRotation, nr, 3) +=
      m.weights * (length_ * loads.y[0] * rotor_.axis.transpose() * m.R * Skew(normal_) * m.turn);
  if (has_flap()) J.block(ri, kFlapRotation, nr, 3) -= m.weights * (share * loads.dflap(0, 0) * f.d_flap);
  J.block(ri, nn, nr, N) -= m.weights * (mid * share * loads.dmu.block(0, 0, 1, N));
  J.block(ri, ri, nr, nr) -= mid * share * m.weights * by_states.row(0);
  J.block(ri, 0, nr, 3) -= m.weights * (share * by_place.row(0)) + (mid * share * loads.y[0]) * gradient.transpose();
}

Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> BeamStripAero::RotorWeightGradient() const {
  Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, 3> gradient = Eigen::MatrixXd::Zero(3, rotor_.num_states);
  if (rotor_.num_states == 3) gradient.rightCols<2>() = rotor_.harmonic_weights;
  return gradient;
}

void BeamStripAero::AddRateParts(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> D,
                                 Eigen::Ref<Eigen::MatrixXd> M) const {
  const Motion m = MotionAt(ctx);
  const Loads loads = Compute(m, FlapOf(m));
  const Eigen::Matrix<double, 12, 3> F = ForceMap(m);
  const int nn = num_node_unknowns(), N = num_states();
  const bool mid = ctx.mode == AnalysisMode::kDynamic;
  // Mid-step forces read the mean rates and the mean accelerations (v_f - v_i)/h; end-point forces the end
  // rates and accelerations themselves.
  const double rate = mid ? 0.5 : 1.0, acceleration = mid ? 1.0 / ctx.h : 1.0;
  Eigen::Ref<Eigen::MatrixXd> acceleration_part = mid ? D : M;
  const double share = ThrustShare(m);  // zero without a rotor
  auto add = [&](Eigen::Ref<Eigen::MatrixXd> target, int column, const RowGradient& g, double factor) {
    target.block(0, column, nn, 3) -= factor * F.topRows(nn) * g.topRows<3>();
    target.block(nn, column, N, 3) += factor * g.bottomRows(N);
    if (has_rotor()) {
      target.block(rotor_local(), column, rotor_.num_states, 3) -= m.weights * (factor * share * g.row(0));
    }
  };
  // Columns: node translation rate (V = R^T (air - v)), body-frame angular rates (the flap's rate and
  // acceleration are the flap node's minus the node's about the pitch axis).
  const Mat3 Rt = m.R.transpose();
  add(D, 0, -loads.dV * Rt, rate);
  add(D, kRotation, loads.dw - loads.dflap.col(1) * pitch_axis_.transpose(), rate);
  add(acceleration_part, 0, -loads.dVdot * Rt, acceleration);
  add(acceleration_part, kRotation, loads.dwdot - loads.dflap.col(2) * pitch_axis_.transpose(), acceleration);
  if (has_flap()) {
    add(D, kFlapRotation, loads.dflap.col(1) * flap_pitch_axis_.transpose(), rate);
    add(acceleration_part, kFlapRotation, loads.dflap.col(2) * flap_pitch_axis_.transpose(), acceleration);
  }
  D.block(nn, nn, N, N) += inflow_.A;
  if (!has_rotor()) return;
  // The inflow's rate turns the air's rate: Vdot changes by -R^T axis per unit nu' at the strip (the states' rate
  // parts, for any scheme), which reads the states' rates through the weights and the strip's velocity through
  // the disc's gradient (A14).
  const int ri = rotor_local(), nr = rotor_.num_states;
  const Rows by_nu_rate = -loads.dVdot * (Rt * rotor_.axis);
  D.block(0, ri, nn, nr) -= F.topRows(nn) * by_nu_rate.head<3>() * m.weights.transpose();
  D.block(nn, ri, N, nr) += by_nu_rate.tail(N) * m.weights.transpose();
  D.block(ri, ri, nr, nr) -= share * m.weights * by_nu_rate[0] * m.weights.transpose();
  add(D, 0, by_nu_rate * m.nu_gradient.transpose(), rate);
}

void BeamStripAero::AddStepWork(const StepContext& ctx, StepWork* work) const {
  if (ctx.mode != AnalysisMode::kDynamic) return;
  const Motion m = MotionAt(ctx);
  const Eigen::Matrix<double, 12, 1> q = ForceMap(m) * Compute(m, FlapOf(m)).y.head<3>();
  const NodeStep& n = (*ctx.nodes)[node_];
  work->external += q.head<3>().dot(n.dx) + q.segment<3>(kRotation).dot(n.theta);
  if (has_flap()) work->external += q.segment<3>(kFlapRotation).dot((*ctx.nodes)[flap_.node].theta);
}

Vec3 BeamStripAero::StripLoads(const StepContext& ctx) const {
  const Motion m = MotionAt(ctx);
  return length_ * Compute(m, FlapOf(m)).y.head<3>();
}

Eigen::Vector3d BeamStripAero::RotorRows(const StepContext& ctx) const {
  Eigen::Vector3d rows = Eigen::Vector3d::Zero();
  if (!has_rotor()) return rows;
  const Motion m = MotionAt(ctx);
  rows.head(rotor_.num_states) = ThrustShare(m) * Compute(m, FlapOf(m)).y[0] * m.weights;
  return rows;
}

double BeamStripAero::FlapAngle(const StepContext& ctx) const { return FlapOf(MotionAt(ctx)).delta[0]; }

}  // namespace flexmbd
