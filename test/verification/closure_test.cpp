// Joints that close kinematic loops (YAML closures:, docs/config.md): a slider-crank whose rod joins the slider
// through a closing universal joint (test/data slider_crank), driven, and swinging freely under gravity, read
// from the files as a user runs them. The loop is a closed form: the slider's travel follows the crank angle.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "flexmbd/io/config_loader.hpp"

#include "closed_forms.hpp"
#include "loop_run.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace closure_test {

constexpr double kPi = 3.14159265358979323846;
constexpr double kCrank = 0.1, kRod = 0.3;  // [m], test/data/urdf/slider_crank.urdf
// Newton ends a step with every constraint row below 1e-11 (docs/theory.md, "Newton iteration"); the slider's
// travel is the crank pin's and the rod's positions through the loop, each off by at most that, times
// l / sqrt(l^2 - r^2) = 1.06 at most: 1e-10 m leaves a margin.
constexpr double kLoopTolerance = 1.0e-10;

// The slider's travel from its start at crank angle 0 (slider at r + l): the rod's far end on the slide.
double SliderTravel(double theta) { return test::SliderTravel(kCrank, kRod, theta); }

ModelSpec SliderCrank() {
  const std::string data = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/";
  return LoadModelSpec(data + "urdf/slider_crank.urdf", data + "yaml/slider_crank.yaml");
}

// The loop run of a slider-crank, with the worst error of the slider's travel against its closed form.
struct SliderCrankRun : test::LoopRun {
  double worst_travel_error = 0;  // [m]
};

SliderCrankRun RunLoop(const ModelSpec& spec) {
  const Model model = BuildModel(spec);
  const int crank = model.FindVariable("crank_hinge"), slide = model.FindVariable("slide");
  double worst_travel_error = 0;
  SliderCrankRun run;
  static_cast<test::LoopRun&>(run) = test::RunLoop(model, [&](const OutputSample& s, const State&) {
    worst_travel_error = std::max(worst_travel_error, std::abs(s.position[slide] - SliderTravel(s.position[crank])));
  });
  run.worst_travel_error = worst_travel_error;
  return run;
}

TEST(Closure, DrivenSliderCrankFollowsItsClosedForm) {
  const ModelSpec spec = SliderCrank();
  const SliderCrankRun run = RunLoop(spec);
  EXPECT_DOUBLE_EQ(run.last.t, 2.5);
  EXPECT_LT(run.worst_travel_error, kLoopTolerance);
  EXPECT_LT(run.worst_constraint, kLoopTolerance);
  // two turns, then held: back at the start, at rest
  const Model model = BuildModel(spec);
  EXPECT_NEAR(run.last.position[model.FindVariable("crank_hinge")], 4.0 * kPi, 1e-12);
  EXPECT_NEAR(run.last.position[model.FindVariable("slide")], 0.0, kLoopTolerance);
  // The drive's work is booked as external work, the scheme's dissipation as numerical dissipation: the books
  // close to the Newton tolerance (1e-6 of each step's terms, accumulated over the steps; measured below 1e-9).
  EXPECT_LT(std::abs(run.books), 1e-8);
  EXPECT_GT(run.last.external_work, 0.0);
}

TEST(Closure, FreeSliderCrankKeepsItsLoopAndEnergyUnderGravity) {
  // Released from rest at crank angle 0 with gravity across the slide, the crank swings the slider to and fro.
  // The energy-preserving scheme keeps the energy at every step to Newton's tolerance, 1e-6 of each step's terms
  // (docs/theory.md (T6)); over about 800 steps the errors partly cancel: measured 3e-9 of the largest kinetic
  // energy (0.38 J), bound 1e-7.
  ModelSpec spec = SliderCrank();
  for (JointSpec& joint : spec.joints) {
    if (joint.name == "crank_hinge") joint.effects[0].drives.clear();
  }
  spec.solver.gravity = Vec3(0.0, -9.81, 0.0);
  spec.solver.integrator = SolverSpec::Integrator::kEnergyPreserving;
  spec.solver.t_end = 3.0;
  const SliderCrankRun run = RunLoop(spec);
  EXPECT_DOUBLE_EQ(run.last.t, 3.0);
  EXPECT_LT(run.worst_travel_error, kLoopTolerance);
  EXPECT_LT(run.worst_constraint, kLoopTolerance);
  EXPECT_LT(run.worst_energy_change, 1e-7);
  EXPECT_GT(run.last.kinetic + std::abs(run.last.potential), 0.01);  // it moves
}

TEST(Closure, RunnerRunsTheSliderCrank) {
  std::ifstream file(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/yaml/slider_crank.yaml");
  std::stringstream yaml;
  yaml << file.rdbuf();
  const std::string output = test::RunnerOutput("test/data/urdf/slider_crank.urdf", yaml.str(), "closure_slider_crank");
  EXPECT_NE(output.find("finished at t = 2.5 s"), std::string::npos) << output;
}

// The slider-crank of test/data with `crank` as the crank hinge's settings and `solver` as the solver's, written
// to a file as a user would: the loader assembles the loop about the crank's set start.
std::string SliderCrankYaml(const std::string& crank, const std::string& solver) {
  return "closures:\n  wrist_pin: {type: universal, parent: rod, child: slider, xyz: [0.3, 0.0, 0.0], axis: [0, 0, 1], "
         "axis2: [0, 1, 0]}\njoints:\n  crank_pin: {type: spherical}\n  crank_hinge: " + crank +
         "\nsolver: " + solver + "\noutput: {rate_hz: 0}\n";
}

ModelSpec LoadSliderCrank(const std::string& yaml_text, const std::string& name) {
  const std::string yaml = testing::TempDir() + name + ".yaml";
  std::ofstream(yaml) << yaml_text;
  return LoadModelSpec(std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/slider_crank.urdf", yaml);
}

TEST(Closure, SliderCrankStartedOffItsUrdfPoseClosesItsLoop) {
  // Released from rest at crank angles set in the YAML (the URDF draws angle 0), under gravity across the slide:
  // the loader moves the slide and the spherical pin to close the loop, and the run keeps it closed.
  for (const std::string angle : {"0.7", "1.5", "2.5", "-2.0"}) {
    const ModelSpec spec = LoadSliderCrank(
        SliderCrankYaml("{initial: {position: " + angle + "}}", "{t_end: 0.3, gravity: [0.0, -9.81, 0.0]}"),
        "closure_slider_crank_start");
    const SliderCrankRun run = RunLoop(spec);
    EXPECT_DOUBLE_EQ(run.last.t, 0.3) << angle;
    EXPECT_LT(run.worst_travel_error, kLoopTolerance) << angle;
    EXPECT_LT(run.worst_constraint, kLoopTolerance) << angle;
    EXPECT_GT(run.last.kinetic, 1e-3) << angle;  // it moves from where it was set
  }
}

TEST(Closure, DrivenCrankStartsOnItsDrive) {
  // One turn at 2 pi rad/s from 1 rad (linear ramp): the crank starts at f(0) turning at f'(0), the slider at its
  // closed-form place and rate (the assembly's round-off, far below the loop tolerance).
  const ModelSpec spec = LoadSliderCrank(
      SliderCrankYaml("{drive: {law: linear_ramp, offset: 1.0, value: 7.283185307179586, duration: 1.0}}",
                      "{t_end: 1.2, gravity: [0.0, 0.0, 0.0]}"),
      "closure_slider_crank_driven");
  const Model model = BuildModel(spec);
  const int crank = model.FindVariable("crank_hinge"), slide = model.FindVariable("slide");
  const State start = model.initial_state();
  EXPECT_DOUBLE_EQ(start.q[crank], 1.0);
  EXPECT_NEAR(start.q[slide], SliderTravel(1.0), kLoopTolerance);
  EXPECT_NEAR(start.qdot[slide], 2.0 * kPi * test::SliderTravelRate(kCrank, kRod, 1.0), kLoopTolerance);
  const SliderCrankRun run = RunLoop(spec);
  EXPECT_DOUBLE_EQ(run.last.t, 1.2);
  EXPECT_LT(run.worst_travel_error, kLoopTolerance);
  EXPECT_LT(run.worst_constraint, kLoopTolerance);
  EXPECT_NEAR(run.last.position[crank], 1.0 + 2.0 * kPi, 1e-12);
}

TEST(Closure, RunnerAssemblesTheSliderCrankOrSaysWhichLoopStaysOpen) {
  const std::string runs = test::RunnerOutput(
      "test/data/urdf/slider_crank.urdf", SliderCrankYaml("{initial: {position: 2.0}}", "{t_end: 0.1}"),
      "closure_slider_crank_assembled");
  EXPECT_NE(runs.find("finished at t = 0.1 s"), std::string::npos) << runs;
  // the slide set at its URDF place as well: the crank at 2 rad cannot reach it
  const std::string refused = test::RunnerOutput(
      "test/data/urdf/slider_crank.urdf",
      SliderCrankYaml("{initial: {position: 2.0}}\n  slide: {initial: {position: 0.0}}", "{t_end: 0.1}"),
      "closure_slider_crank_open", 2);
  EXPECT_NE(refused.find("closures.wrist_pin: the loop does not close: the child's joint frame lies ["),
            std::string::npos)
      << refused;
}

TEST(Closure, WingAileronBracketsLeaveTheAileronOnlyItsFlap) {
  // config/wing_aileron (issue 17, case 2), structure only: wing and aileron beams (19 and 7 nodes, the wing
  // clamped: 108 + 42 freedoms) and two brackets (12) joined by a universal, a revolute, a prismatic joint and the
  // closing spherical one (4 + 5 + 5 + 3 = 17 constraints): 145 degrees of freedom, of which only the aileron's
  // rotation about its hinge line in its freeplay (no hinge spring) is a rigid-body mode. A redundant or a missing
  // constraint of the loop changes either count.
  std::ifstream file(std::string(FLEXMBD_SOURCE_DIR) + "/config/wing_aileron/wing_aileron_modes.yaml");
  std::stringstream yaml;
  yaml << file.rdbuf();
  const std::string output =
      test::RunnerOutput("config/wing_aileron/wing_aileron.urdf", yaml.str(), "closure_wing_aileron");
  EXPECT_NE(output.find("145 degrees of freedom, 1 rigid-body modes"), std::string::npos) << output;
}

}  // namespace closure_test
}  // namespace flexmbd
