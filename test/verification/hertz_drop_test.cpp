// A ball on Hertz stops (issue 13; docs/theory.md (C2b), (C4), (C6)), from its YAML files at default settings as a
// user runs them, against closed forms: dropped onto a lossless stop, its rebound, the contact's duration and the
// bounce period, and how their errors fall with error_tol; thrown onto a stop of restitution 0.7 without gravity,
// its rebound. Every accepted step is a sample.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "closed_forms.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace hertz_drop_test {

constexpr double kG = 9.81, kMass = 1.0, kStiffness = 1.0e8, kExponent = 1.5;
constexpr double kStop = -0.5, kDrop = 0.5;  // [m]: the stop on the slide, the height the ball falls onto it
const double kImpactSpeed = std::sqrt(2.0 * kG * kDrop);

ModelSpec Case(const std::string& yaml) {
  const std::string data = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  return LoadModelSpec(data + "urdf/ball_drop.urdf", data + "yaml/" + yaml);
}

// When the gap closed and opened again, interpolated linearly between the steps around each crossing: the gap moves
// at the impact speed there under the weight alone (the Hertz force vanishes as a^1.5), so the interpolation is
// off by g h^2 / (8 v), below 1e-8 s for the steps of 1e-4 s and less that reach the stop.
struct Contact {
  double begin = 0, end = 0;  // [s]
};

struct DropRun {
  std::vector<Contact> contacts;
  std::vector<OutputSample> samples;
  double books = 0;       // largest |E + dissipated - E(0)| over the samples [J] (no loads: no external work)
  double throughput = 0;  // the energy through the books: E(0) and what was dissipated [J]
};

DropRun RunCase(const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  DropRun run;
  simulation.Run([&run](const OutputSample& s) { run.samples.push_back(s); });
  const double e0 = run.samples.front().total();
  for (size_t k = 0; k < run.samples.size(); ++k) {
    const OutputSample& s = run.samples[k];
    const double removed = s.dissipated + s.numerical_dissipation;
    run.books = std::max(run.books, std::abs(s.total() + removed - e0));
    run.throughput = std::abs(e0) + removed;
    if (k == 0) continue;
    const OutputSample& before = run.samples[k - 1];
    const double gap_before = before.position[0] - kStop, gap = s.position[0] - kStop;
    const bool closes = gap_before >= 0 && gap < 0, opens = gap_before < 0 && gap >= 0;
    if (!closes && !opens) continue;
    const double t = before.t + (s.t - before.t) * gap_before / (gap_before - gap);
    if (closes) run.contacts.push_back({t, std::nan("")});
    else if (!run.contacts.empty()) run.contacts.back().end = t;
  }
  return run;
}

// Speed at which the ball left contact c: the flight to the next contact, between the same height under gravity
// alone, lasts 2 v / g.
double ReboundSpeed(const DropRun& run, size_t c) {
  return kG * (run.contacts[c + 1].begin - run.contacts[c].end) / 2.0;
}

double ContactDuration(double speed) { return test::ElasticContactDuration(kMass, kStiffness, kExponent, speed, kG); }

// The largest relative errors of the contacts followed by a flight: rebound against impact speed, duration against
// the closed form.
struct DropErrors {
  double rebound = 0, duration = 0;
};

DropErrors ErrorsAt(double error_tol) {
  ModelSpec spec = Case("hertz_ball_drop.yaml");
  spec.solver.error_tol = error_tol;
  const DropRun run = RunCase(spec);
  DropErrors errors;
  EXPECT_EQ(run.contacts.size(), 3u) << "error_tol " << error_tol;
  double impact = kImpactSpeed;
  for (size_t c = 0; c + 1 < run.contacts.size(); ++c) {
    const double rebound = ReboundSpeed(run, c);
    errors.rebound = std::max(errors.rebound, std::abs(rebound / impact - 1.0));
    const double duration = run.contacts[c].end - run.contacts[c].begin;
    errors.duration = std::max(errors.duration, std::abs(duration / ContactDuration(impact) - 1.0));
    impact = rebound;
  }
  return errors;
}

TEST(HertzDrop, ReboundContactAndBouncePeriodMatchTheClosedFormsAtTheDefaultTolerance) {
  for (const auto integrator : {SolverSpec::Integrator::kEnergyDecaying, SolverSpec::Integrator::kEnergyPreserving}) {
    ModelSpec spec = Case("hertz_ball_drop.yaml");
    spec.solver.integrator = integrator;
    const DropRun run = RunCase(spec);
    const bool decaying = integrator == SolverSpec::Integrator::kEnergyDecaying;
    // Three impacts in 2 s, at 0.319 s and one bounce period apart.
    ASSERT_EQ(run.contacts.size(), 3u) << "energy decaying " << decaying;
    const double period = 2.0 * kImpactSpeed / kG + ContactDuration(kImpactSpeed);
    // The aim for the rebound at the default tolerance: 1e-3 of the impact speed (measured 2.5e-4 with the
    // energy-decaying scheme, whose dissipation takes it; round-off with the energy-preserving one).
    constexpr double kReboundTolerance = 1.0e-3;
    // The contact's duration carries the scheme's phase error, (omega h)^2 / 12 at the steps the default tolerance
    // takes in it (4.4e-5 s against pi / omega = 1.6 ms: 6e-4 for a harmonic contact, more where the Hertz law
    // stiffens); measured 1.1e-3 with either scheme.
    constexpr double kDurationTolerance = 3.0e-3;
    // The bounce period is the flight, 2 v / g, and the contact (1/400 of it): each rebound off by 1e-3 moves the
    // flights after it by 1e-3.
    constexpr double kPeriodTolerance = 1.0e-3;
    double impact = kImpactSpeed;
    for (size_t c = 0; c + 1 < run.contacts.size(); ++c) {
      const double rebound = ReboundSpeed(run, c), duration = ContactDuration(impact);
      EXPECT_NEAR(rebound / impact, 1.0, kReboundTolerance) << "contact " << c << ", energy decaying " << decaying;
      EXPECT_NEAR(run.contacts[c].end - run.contacts[c].begin, duration, kDurationTolerance * duration)
          << "contact " << c << ", energy decaying " << decaying;
      EXPECT_NEAR(run.contacts[c + 1].begin - run.contacts[c].begin, period, (c + 1) * kPeriodTolerance * period)
          << "contact " << c << ", energy decaying " << decaying;
      impact = rebound;
    }
    // The books close to Newton's tolerance times the energy that passed through them (T6), as antenna_case_test.
    EXPECT_LT(run.books, spec.solver.tol * run.throughput) << "energy decaying " << decaying;
  }
}

TEST(HertzDrop, ReboundAndContactErrorsFallWithTheTolerance) {
  // The issue asks the error to fall at least 10 times for every 100 times of tolerance (a second-order scheme
  // under a tolerance on the error per unit step gives 10x; measured 21x). Before the onset of a contact was judged
  // at its own pace (C6), the durations at 1e-3 and 1e-5 were 6.1e-3 and 1.7e-3 off (3.6x), and 0.28 at 1e-4.
  constexpr double kLeastFall = 10.0;
  DropErrors before = ErrorsAt(1.0e-3);
  for (double error_tol : {1.0e-5, 1.0e-7}) {
    const DropErrors now = ErrorsAt(error_tol);
    EXPECT_LT(now.rebound * kLeastFall, before.rebound)
        << "error_tol " << error_tol << ": rebound error " << now.rebound << " after " << before.rebound;
    EXPECT_LT(now.duration * kLeastFall, before.duration)
        << "error_tol " << error_tol << ": duration error " << now.duration << " after " << before.duration;
    before = now;
  }
}

TEST(HertzThrown, ReboundsWithTheGivenRestitution) {
  // Without gravity the Hunt-Crossley damping number of (C4) returns exactly e of the approach speed, whatever the
  // law. The aim at the default tolerance: 1e-3 of it.
  const ModelSpec spec = Case("hertz_ball_thrown.yaml");
  const double restitution = spec.joints.at(0).effects.at(0).stops.at(0).restitution;
  const double speed = -spec.joints.at(0).initial_velocity.at(0);
  const DropRun run = RunCase(spec);
  ASSERT_EQ(run.contacts.size(), 1u);
  ASSERT_FALSE(std::isnan(run.contacts[0].end));
  constexpr double kReboundTolerance = 1.0e-3;
  EXPECT_NEAR(run.samples.back().velocity[0] / speed, restitution, kReboundTolerance * restitution);
  EXPECT_LT(run.books, spec.solver.tol * run.throughput);
}

}  // namespace hertz_drop_test
}  // namespace flexmbd
