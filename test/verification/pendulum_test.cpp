// Rigid pendulum checks against closed forms.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "case_builders.hpp"
#include "closed_forms.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace pendulum_test {

using test::EllipticK;

// Times at which the joint rate changes sign, linearly interpolated between samples.
std::vector<double> RateSignChanges(const std::vector<OutputSample>& samples) {
  std::vector<double> times;
  for (size_t k = 1; k < samples.size(); ++k) {
    const double a = samples[k - 1].velocity[0], b = samples[k].velocity[0];
    if (a * b < 0) times.push_back(samples[k - 1].t + (samples[k].t - samples[k - 1].t) * a / (a - b));
  }
  return times;
}

TEST(Pendulum, PeriodFromNinetyDegreesMatchesEllipticIntegral) {
  // Physical pendulum: equivalent length L = (I_cm + m a^2) / (m a); exact period 4 K(sin(theta0/2)) sqrt(L/g).
  const double m = 1.0, arm = 1.0, i_cm = 1.0e-3, g = 9.81;
  ModelSpec spec = test::Pendulum(m, arm, i_cm);
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.dt = 1.0e-3;
  spec.solver.t_end = 5.0;
  spec.solver.tol = 1.0e-10;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  std::vector<OutputSample> samples;
  simulation.Run([&](const OutputSample& s) { samples.push_back(s); });
  const std::vector<double> turns = RateSignChanges(samples);
  ASSERT_GE(turns.size(), 3u);
  const double length = (i_cm + m * arm * arm) / (m * arm);
  const double exact = 4.0 * EllipticK(std::sin(M_PI / 4.0)) * std::sqrt(length / g);
  // Trapezoidal-family phase error is (w h)^2 / 12 ~ 1e-6 here; linear interpolation of the turning instants
  // adds O(h^2) too. 1e-4 relative is the requirement and leaves a factor of ~50.
  constexpr double kPeriodTolerance = 1.0e-4;
  EXPECT_NEAR((turns[2] - turns[0]) / exact, 1.0, kPeriodTolerance);
}

}  // namespace pendulum_test
}  // namespace flexmbd
