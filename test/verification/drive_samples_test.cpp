// Output samples of driven joints where a step does not start from the rates the last step ended with: inside the
// step after a drive's rate jump (a table's stop, a commanded set-point), and at the start of a run, whose forces
// a state does not give (docs/config.md, "Output"). A 2 kg body lifted along z by a prismatic or cylindrical joint
// (test/data/urdf/offset_body.urdf, from the explore round's drive/body.urdf), YAML at default settings.

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "yaml_text.hpp"

namespace flexmbd {
namespace drive_samples_test {

constexpr double kMass = 2.0, kGravity = 9.81, kOffsetX = 0.3;  // [kg, m/s^2, m] of offset_body.urdf

Model BodyModel(const std::string& yaml) {
  const std::string urdf = test::ReadFile(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/offset_body.urdf");
  return BuildModel(LoadModelSpecFromStrings(urdf, "offset_body.urdf", YAML::Load(yaml), "test.yaml"));
}

std::vector<OutputSample> AllSamples(const Model& model) {
  std::vector<OutputSample> samples;
  Simulation(model).Run([&](const OutputSample& s) { samples.push_back(s); });
  return samples;
}

TEST(DriveSamples, SamplesAfterATableStopsTheLiftReadItsRestAndItsWeight) {
  // explore round 23's kink/slide_stop.yaml: lifted at 0.5 m/s for 1 s, then held. Before, the samples over 1.01-1.05
  // s read 0.417 ... 0.083 m/s, interpolated from the rate before the stop.
  const Model model = BodyModel(
      "joints: {j: {type: prismatic, drive: {law: table, times: [0.0, 1.0], values: [0.0, 0.5]}}}\n"
      "solver: {t_end: 2.0}\noutput: {rate_hz: 100}\n");
  double worst_rate = 0, worst_effort = 0;
  int held = 0;
  for (const OutputSample& s : AllSamples(model)) {
    const bool lifting = s.t <= 1.0 + 1.0e-9;  // the sample at the stop ends the last step of the lift
    worst_rate = std::max(worst_rate, std::abs(s.velocity[0] - (lifting ? 0.5 : 0.0)));
    worst_effort = std::max(worst_effort, std::abs(s.effort[0] - kMass * kGravity));
    held += lifting ? 0 : 1;
  }
  EXPECT_EQ(held, 100);
  // Motion at constant rates has no alternating mode (q''' = 0), and the projection at the stop meets the rate after
  // it: rates and the weight are exact to the Newton tolerance (1e-6 relative by default) of the 0.5 m/s and 19.6 N.
  constexpr double kNewtonTolerance = 1.0e-6;
  EXPECT_LT(worst_rate, kNewtonTolerance * 0.5);
  EXPECT_LT(worst_effort, kNewtonTolerance * kMass * kGravity);
}

TEST(DriveSamples, TheFirstSampleCarriesTheForcesOfTheInitialMotion) {
  // s = A cos(w t) along z: the effort m (g + s'') is m (g - A w^2) at t = 0, and the joint holds the moment of the
  // offset centre of mass, m (g + s'') x_c about y. Before, both read 0 in the first sample.
  constexpr double kAmplitude = 0.05, kOmega = 4.0 * M_PI;
  const Model model = BodyModel(
      "joints: {j: {type: prismatic, drive: {law: sine, amplitude: 0.05, frequency: 2.0, phase: 1.5707963267948966}}}\n"
      "solver: {t_end: 0.1}\noutput: {rate_hz: 1000}\n");
  const std::vector<OutputSample> samples = AllSamples(model);
  const OutputSample& first = samples.front();
  ASSERT_EQ(first.t, 0.0);
  const double lift = kMass * (kGravity - kAmplitude * kOmega * kOmega);
  // The mean forces of a step of 1e-3 of the first step from the state: s''' = 0 at t = 0, so they are the start's to
  // O(h^2), and Newton's force rows hold them to its tolerance (1e-6) of their largest terms, the weight 19.6 N and
  // the inertia m A w^2 = 15.8 N, over a few iterations: three times that (measured 4.0e-5 N).
  const double force_tolerance = 3.0e-6 * kMass * (kGravity + kAmplitude * kOmega * kOmega);
  EXPECT_NEAR(first.effort[0], lift, force_tolerance);
  EXPECT_NEAR(first.reaction_moment[0].norm(), lift * kOffsetX, force_tolerance * kOffsetX);
  // The samples in the first step interpolate from it: within the step's change of the lift, m A w^3 h (w h <= 0.06).
  for (size_t k = 1; k < 4; ++k) {
    const double t = samples[k].t;
    EXPECT_NEAR(samples[k].effort[0], kMass * (kGravity - kAmplitude * kOmega * kOmega * std::cos(kOmega * t)), 0.1);
  }
}

TEST(DriveSamples, ASetpointIsFollowedFromTheFirstSampleAfterTheCommand) {
  // explore round 23's ros/setpoint: a cylindrical joint held, then commanded to s = 0.05 m at t_c with the node's
  // default lag tau = 0.1 s: s = S (1 - exp(-x)), x = (t - t_c) / tau, rate S/tau exp(-x) = 0.5 m/s at t_c, effort
  // m (g + s'') = m (g - S/tau^2 exp(-x)). Before, the first step after the command was dt_max = tau, and the first
  // 200 Hz sample read 0.0066 m/s against 0.476 m/s; efforts were off by up to 30 N over 0.25 s.
  constexpr double kSetpoint = 0.05, kLag = 0.1;
  const Model model = BodyModel(
      "joints: {j: {type: cylindrical, variables: [{drive: {law: constant, value: 0.2}}, "
      "{drive: {law: constant, value: 0.0}}]}}\nsolver: {t_end: 3.0}\noutput: {rate_hz: 200}\n");
  Simulation simulation(model);
  std::vector<OutputSample> samples;
  const auto keep = [&](const OutputSample& s) { samples.push_back(s); };
  simulation.Begin(keep);
  simulation.AdvanceTo(2.0, 3.0, keep);
  const double t_c = simulation.state().t;
  const size_t before = samples.size();
  simulation.SetSetpoint(1, kSetpoint, kLag);
  simulation.AdvanceTo(3.0, 3.0, keep);
  double worst_position = 0, worst_rate = 0, worst_effort = 0;
  for (size_t k = before; k < samples.size(); ++k) {
    const OutputSample& s = samples[k];
    const double decay = std::exp(-(s.t - t_c) / kLag);
    worst_position = std::max(worst_position, std::abs(s.position[1] - kSetpoint * (1.0 - decay)));
    worst_rate = std::max(worst_rate, std::abs(s.velocity[1] - kSetpoint / kLag * decay));
    worst_effort =
        std::max(worst_effort, std::abs(s.effort[1] - kMass * (kGravity - kSetpoint / (kLag * kLag) * decay)));
  }
  RecordProperty("first_step", std::to_string(samples[before].dt));
  RecordProperty("worst_position", std::to_string(worst_position));
  RecordProperty("worst_rate", std::to_string(worst_rate));
  RecordProperty("worst_effort", std::to_string(worst_effort));
  // From the command on the error test holds h^2 |q'''| within 12 error_tol |q'|peak (T12: h^3 |q'''| / 12 against
  // error_tol h |q'|peak, which the first step's h = tau sqrt(12 error_tol) meets), twice that for the RMS over the
  // model's few entries. The end rates carry h^2 |q'''| / 6 (T11), linear interpolation between them h^2 |q'''| / 8 and
  // of positions h^2 |q''| / 8 = tau h^2 |q'''| / 8; the efforts, the steps' mean forces, lag the sample by up to the
  // step's half and carry the end rates' alternation, m h |q'''| (1/2 + 1/6), largest at the first step, where h |q'''|
  // is largest (the estimate grows h as |q'''|^(-1/2)).
  constexpr double kErrorTol = 1.0e-4;  // solver.error_tol's default
  const double rate0 = kSetpoint / kLag, held = 2.0 * 12.0 * kErrorTol * rate0;
  const double first_step = kLag * std::sqrt(12.0 * kErrorTol);
  EXPECT_LT(worst_position, held * kLag / 8.0);
  EXPECT_LT(worst_rate, held * (1.0 / 6.0 + 1.0 / 8.0));
  EXPECT_LT(worst_effort, 1.1 * kMass * first_step * rate0 / (kLag * kLag) * (0.5 + 1.0 / 6.0));
}

}  // namespace drive_samples_test
}  // namespace flexmbd
