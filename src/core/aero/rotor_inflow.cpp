// A rotor's induced inflow with the apparent mass of its air: uniform (docs/theory.md, (A13)) or with Pitt and
// Peters' first harmonics (A14).

#include "flexmbd/aero/rotor_inflow.hpp"

#include <cmath>
#include <tuple>

#include "flexmbd/aero/beam_strip_aero.hpp"
#include "flexmbd/aero/pitt_peters_disc.hpp"
#include "flexmbd/math/time_function.hpp"

namespace flexmbd {
namespace {
// The harmonics' apparent mass per rho R^3: Pitt and Peters' 16 / (45 pi) times the pi of rho pi R^3 (A14).
constexpr double kHarmonicMass = 16.0 / 45.0;
}  // namespace

std::pair<Vec3, Vec3> DiscAxes(const Vec3& axis) {
  const Vec3 reference = std::abs(axis.x()) < std::sqrt(0.5) ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 e_c = (reference - reference.dot(axis) * axis).normalized();
  return {e_c, axis.cross(e_c)};
}

RotorInflow::RotorInflow(const AeroRotorSpec& spec, const AeroFlowSpec& flow, int first_state_unknown)
    : name_(spec.name),
      harmonic_(spec.inflow == AeroRotorSpec::Inflow::kHarmonic),
      num_states_(RotorInflowStates(spec)),
      axis_(spec.axis),
      center_(spec.center),
      radius_(spec.radius),
      density_(flow.density),
      disc_area_(M_PI * spec.radius * spec.radius),
      apparent_mass_(8.0 / 3.0 * flow.density * std::pow(spec.radius, 3)),
      free_stream_(flow.free_stream),
      gust_(flow.gust),
      gust_scale_(flow.gust_scale) {
  std::tie(e_c_, e_s_) = DiscAxes(axis_);
  for (int k = 0; k < num_states(); ++k) unknowns_.push_back(first_state_unknown + k);
}

RotorStates RotorInflow::Momentum(double t, const RotorStates& nu, StateSlope* slope) const {
  const Vec3 air = free_stream_ + Evaluate(gust_scale_, t) * gust_;
  const double climb = -axis_.dot(air);
  const double k = density_ * disc_area_;
  if (harmonic_) {
    const Vec3 in_plane = air + climb * axis_;
    const DiscMomentum m = PittPetersMomentum(climb, Eigen::Vector2d(e_c_.dot(in_plane), e_s_.dot(in_plane)), nu, k);
    *slope = m.slope;
    return m.value;
  }
  const double in_plane = (air + climb * axis_).norm();
  const double through = climb + nu[0], speed = std::hypot(in_plane, through);  // V_c + nu and V_T
  // d(V_T nu)/d nu = V_T + nu (V_c + nu) / V_T; at V_T = 0 (no stream, no inflow) both terms vanish.
  *slope = StateSlope::Constant(1, 1, 2.0 * k * (speed + (speed > 0.0 ? nu[0] * through / speed : 0.0)));
  return RotorStates::Constant(1, 2.0 * k * speed * nu[0]);
}

namespace {
// The states' values and rates at ctx.
void ReadStates(const StepContext& ctx, int first, int n, RotorStates* value, RotorStates* rate) {
  value->resize(n);
  rate->resize(n);
  for (int k = 0; k < n; ++k) {
    const ElementStateStep& x = (*ctx.element_states)[first + k];
    (*value)[k] = x.value;
    (*rate)[k] = x.rate;
  }
}
}  // namespace

void RotorInflow::AddResidual(const StepContext& ctx, Eigen::Ref<Eigen::VectorXd> r,
                              Eigen::Ref<Eigen::VectorXd> magnitude) const {
  const int n = num_states();
  if (ctx.mode == AnalysisMode::kStatic) {
    // An equilibrium keeps the inflow it has (docs/theory.md, (A13)): the increment's own rows.
    for (int k = 0; k < n; ++k) {
      r[k] += (*ctx.element_states)[first_state() + k].x_f - ctx.start->element_states[first_state() + k];
    }
    return;
  }
  RotorStates nu, rate;
  ReadStates(ctx, first_state(), n, &nu, &rate);
  StateSlope slope;
  const RotorStates momentum = Momentum(ctx.force_time(), nu, &slope);
  for (int k = 0; k < n; ++k) {
    const double lag = (k == 0 ? apparent_mass_ : kHarmonicMass * density_ * std::pow(radius_, 3)) * rate[k];
    r[k] += lag + momentum[k];
    magnitude[k] += std::abs(lag) + std::abs(momentum[k]);
  }
}

void RotorInflow::AddTangent(const StepContext& ctx, Eigen::Ref<Eigen::MatrixXd> J) const {
  const int n = num_states();
  if (ctx.mode == AnalysisMode::kStatic) {
    J.topLeftCorner(n, n) += Eigen::MatrixXd::Identity(n, n);
    return;
  }
  RotorStates nu, rate;
  ReadStates(ctx, first_state(), n, &nu, &rate);
  StateSlope slope;
  Momentum(ctx.force_time(), nu, &slope);
  J.topLeftCorner(n, n) += ctx.mid_rate() * slope;
}

void RotorInflow::AddRateParts(const StepContext&, Eigen::Ref<Eigen::MatrixXd> D, Eigen::Ref<Eigen::MatrixXd>) const {
  D(0, 0) += apparent_mass_;
  for (int k = 1; k < num_states(); ++k) D(k, k) += kHarmonicMass * density_ * std::pow(radius_, 3);
}

Eigen::Vector3d RotorInflow::Loads(const StepContext& ctx) const {
  Eigen::Vector3d loads = Eigen::Vector3d::Zero();
  for (const BeamStripAero* strip : strips_) loads += strip->RotorRows(ctx);
  return Eigen::Vector3d(loads[0], radius_ * loads[1], radius_ * loads[2]);
}

}  // namespace flexmbd
