// The generalized-alpha option against closed forms: accuracy, order, damping of unresolved modes, constraints.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_builders.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "flexmbd/solver/step_context_builder.hpp"

namespace flexmbd {
namespace generalized_alpha_test {

constexpr double kMass = 2.0, kStiffness = 50.0, kAmplitude = 0.1;  // [kg], [N/m], [m]

// The mass-spring of test::MassSpring without gravity, stepped by generalized-alpha.
ModelSpec MassSpring(double dt, double t_end, double rho_inf) {
  ModelSpec spec =
      test::MassSpring(kMass, kStiffness, kAmplitude, SolverSpec::Integrator::kGeneralizedAlpha, dt, t_end);
  spec.solver.rho_inf = rho_inf;
  spec.solver.gravity = Vec3::Zero();
  spec.solver.dt_max = dt;
  return spec;
}

std::vector<OutputSample> RunSamples(const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  std::vector<OutputSample> samples;
  simulation.Run([&](const OutputSample& s) { samples.push_back(s); });
  return samples;
}

TEST(GeneralizedAlpha, SecondOrderOnSmoothMotion) {
  // The spring force at t = 0 is not zero but the scheme starts from zero accelerations: the start-up error
  // decays (rho_inf < 1) and the global error at t = 1 s still falls by ~4 when dt halves.
  const double w = std::sqrt(kStiffness / kMass);
  std::vector<double> errors;
  for (double dt : {0.01, 0.005, 0.0025}) {
    const std::vector<OutputSample> s = RunSamples(MassSpring(dt, 1.0, 0.8));
    errors.push_back(std::abs(s.back().position[0] - kAmplitude * std::cos(w * 1.0)));
  }
  // Second order: ratios near 4; 3.5 to 4.5 rejects first (2) and third (8) order.
  for (size_t k = 1; k < errors.size(); ++k) {
    EXPECT_GT(errors[k - 1] / errors[k], 3.5) << "dt halving " << k;
    EXPECT_LT(errors[k - 1] / errors[k], 4.5) << "dt halving " << k;
  }
}

TEST(GeneralizedAlpha, DampsUnresolvedModeAtRhoInf) {
  // At w h -> infinity the three roots of the scheme all equal -rho_inf (Chung and Hulbert 1993), so the
  // position of an unresolved mode decays like p(n) rho_inf^n with p a quadratic polynomial.
  constexpr double kRhoInf = 0.8;
  const double w = std::sqrt(kStiffness / kMass);
  const std::vector<OutputSample> s = RunSamples(MassSpring(1000.0 / w, 80 * 1000.0 / w, kRhoInf));
  ASSERT_EQ(s.size(), 81u);
  // Geometric mean of the per-step ratio over steps 40..80: rho_inf times at most (80/40)^(2/40) = 1.035 from
  // the polynomial; 1% more covers the O(1/(w h)) = 1e-3 shift of the roots.
  const double rate = std::pow(std::abs(s[80].position[0]) / std::abs(s[40].position[0]), 1.0 / 40.0);
  EXPECT_GT(rate, 0.99 * kRhoInf);
  EXPECT_LT(rate, 1.01 * kRhoInf * std::pow(2.0, 2.0 / 40.0));
}

TEST(GeneralizedAlpha, PendulumPeriodMatchesEllipticIntegral) {
  // Same reference as Pendulum.PeriodFromNinetyDegreesMatchesEllipticIntegral: 4 K(sin 45 deg) sqrt(L/g).
  ModelSpec spec = test::Pendulum(1.0, 1.0, 1.0e-3);
  spec.solver.integrator = SolverSpec::Integrator::kGeneralizedAlpha;
  spec.solver.rho_inf = 0.9;
  spec.solver.dt = 1.0e-3;
  spec.solver.t_end = 5.0;
  spec.solver.tol = 1.0e-10;
  const std::vector<OutputSample> s = RunSamples(spec);
  std::vector<double> turns;
  for (size_t k = 1; k < s.size(); ++k) {
    const double a = s[k - 1].velocity[0], b = s[k].velocity[0];
    if (a * b < 0) turns.push_back(s[k - 1].t + (s[k].t - s[k - 1].t) * a / (a - b));
  }
  ASSERT_GE(turns.size(), 3u);
  const double k_mod = std::sin(M_PI / 4.0);
  double a = 1.0, b = std::sqrt(1.0 - k_mod * k_mod);
  for (int i = 0; i < 40; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  const double length = (1.0e-3 + 1.0) / 1.0;
  const double exact = 4.0 * (M_PI / (2.0 * a)) * std::sqrt(length / 9.81);
  // Generalized-alpha's period error is O((w h)^2) like the trapezoidal rule's, plus its numerical damping's
  // O(h^2) frequency shift: both ~1e-6 here. The 1e-4 leaves margin.
  constexpr double kPeriodTolerance = 1.0e-4;
  EXPECT_NEAR((turns[2] - turns[0]) / exact, 1.0, kPeriodTolerance);
}

TEST(GeneralizedAlpha, DoublePendulumConstraintsHold) {
  ModelSpec spec = test::DoublePendulum(1.0, 0.5, 0.02);
  spec.solver.integrator = SolverSpec::Integrator::kGeneralizedAlpha;
  spec.solver.dt = 0.01;
  spec.solver.t_end = 10.0;
  spec.solver.tol = 1.0e-10;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  double worst = 0;
  StepContextBuilder builder(model);
  simulation.Run([&](const OutputSample&) {
    const StepContext& ctx = builder.AtState(simulation.state());
    for (const Joint* joint : model.joints()) {
      worst = std::max(worst, joint->ConstraintValues(ctx).cwiseAbs().maxCoeff());
    }
  });
  // Index-3: constraints solved to kConstraintTolerance = 1e-11 at every step; the issue asks for 1e-10.
  constexpr double kConstraintLimit = 1.0e-10;
  EXPECT_LT(worst, kConstraintLimit);
}

}  // namespace generalized_alpha_test
}  // namespace flexmbd
