// The wing with aileron of issue 17, case 2 (config/wing_aileron): the flutter speed without freeplay (the hinge's
// stops closed into a spring) through the runner's airspeed sweep, the wing's strips carrying the aileron as their
// flap (docs/theory.md, (A10); docs/validation.md).

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/eigen_analysis.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace {

const std::string kDir = std::string(FLEXMBD_SOURCE_DIR) + "/config/wing_aileron/";

std::string ReadFile(const std::string& path) {
  std::ifstream file(path);
  return std::string((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
}

// Modes growing at speed U (damping ratio below -1e-6 at a frequency below 10% of the frequency scale: the
// round-off margins of theory (E9)), by an eigen-analysis of flutter_sweep.yaml's model at that one speed, about the
// same undeformed state as the sweep.
int GrowingModes(double U) {
  ModelSpec spec = LoadModelSpec(kDir + "wing_aileron.urdf", kDir + "flutter_sweep.yaml");
  spec.aero_flow.free_stream = Vec3(0.0, U, 0.0);
  spec.solver.eigen.sweep_airspeed.clear();
  const Model model = BuildModel(spec);
  const EigenResult result = EigenAnalysis(model, model.initial_state(), EigenOptions{});
  int growing = 0;
  for (const Mode& mode : result.modes) {
    growing += !mode.rigid_body && mode.damping_ratio < -1.0e-6 && mode.frequency_hz < 0.1 * result.frequency_scale_hz;
  }
  return growing;
}

TEST(WingAileron, RunnerFlutterSpeedIsWhereAModeStartsToGrow) {
  // Published (issue 17, case 2): 560 ft/s = 170.69 m/s. Compared in docs/validation.md, not here: this model's
  // strips flutter far below it (see there for what the source's data leave open).
  constexpr double kPublished = 560 * 0.3048;
  const std::string output =
      test::RunnerOutput("config/wing_aileron/wing_aileron.urdf", ReadFile(kDir + "flutter_sweep.yaml"), "wing_aileron_sweep");
  const std::vector<test::Crossing> crossings = test::RunnerCrossings(output);
  ASSERT_FALSE(crossings.empty()) << output;
  ASSERT_EQ(crossings.front().kind, "flutter") << output;  // flutter lines come first, in order of speed
  const double speed = crossings.front().speed;
  std::printf("flutter at %.6g m/s (%.4g Hz), %.4g of the published %.5g m/s\n", speed, crossings.front().frequency_hz,
              speed / kPublished, kPublished);
  // The runner brackets the change to 0.01%: 0.1% (the accuracy) either side, the one-speed analyses must
  // find one more growing mode above than below.
  constexpr double kAccuracy = 1.0e-3;
  EXPECT_EQ(GrowingModes(speed * (1.0 + kAccuracy)), GrowingModes(speed * (1.0 - kAccuracy)) + 1) << output;
}

}  // namespace
}  // namespace flexmbd
