// A rotor's uniform induced inflow with the apparent mass of its air (docs/theory.md, (A13)).

#include "flexmbd/aero/rotor_inflow.hpp"

#include <cmath>

#include "flexmbd/aero/beam_strip_aero.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {

RotorInflow::RotorInflow(const AeroRotorSpec& spec, const AeroFlowSpec& flow, int state_unknown)
    : name_(spec.name),
      axis_(spec.axis),
      density_(flow.density),
      disc_area_(M_PI * spec.radius * spec.radius),
      apparent_mass_(8.0 / 3.0 * flow.density * std::pow(spec.radius, 3)),
      free_stream_(flow.free_stream),
      gust_(flow.gust),
      gust_scale_(flow.gust_scale) {
  unknowns_.push_back(state_unknown);
}

double RotorInflow::Momentum(double t, double nu, double* slope) const {
  const Vec3 air = free_stream_ + Evaluate(gust_scale_, t) * gust_;
  const double climb = -axis_.dot(air), in_plane = (air + climb * axis_).norm();
  const double through = climb + nu, speed = std::hypot(in_plane, through);  // V_c + nu and V_T
  const double k = 2.0 * density_ * disc_area_;
  // d(V_T nu)/d nu = V_T + nu (V_c + nu) / V_T; at V_T = 0 (no stream, no inflow) both terms vanish.
  *slope = k * (speed + (speed > 0.0 ? nu * through / speed : 0.0));
  return k * speed * nu;
}

void RotorInflow::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                              Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const ElementStateStep& x = (*ctx.element_states)[first_state()];
  if (ctx.mode == AnalysisMode::kStatic) {
    // An equilibrium keeps the inflow it has (docs/theory.md, (A13)): the increment's own row.
    r[0] += x.x_f - ctx.start->element_states[first_state()];
    return;
  }
  const double t = ctx.force_time();
  double slope = 0;
  const double lag = apparent_mass_ * x.rate, momentum = Momentum(t, x.value, &slope);
  r[0] += lag + momentum;
  magnitude[0] += std::abs(lag) + std::abs(momentum);
}

void RotorInflow::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  if (ctx.mode == AnalysisMode::kStatic) {
    J(0, 0) += 1.0;
    return;
  }
  const double t = ctx.force_time();
  double slope = 0;
  Momentum(t, (*ctx.element_states)[first_state()].value, &slope);
  J(0, 0) += ctx.mid_rate() * slope;
}

void RotorInflow::AddRateParts(const StepContext&, Eigen::Ref<Eigen::MatrixXd> D, Eigen::Ref<Eigen::MatrixXd>) const {
  D(0, 0) += apparent_mass_;
}

double RotorInflow::Thrust(const StepContext& ctx) const {
  double thrust = 0;
  for (const BeamStripAero* strip : strips_) thrust += strip->Thrust(ctx);
  return thrust;
}

}  // namespace flexmbd
