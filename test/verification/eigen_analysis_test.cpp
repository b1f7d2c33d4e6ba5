// Eigen-analysis against closed forms (docs/theory.md, "Eigen-analysis"): natural frequencies and damping
// ratios of oscillators and pendulums, rigid-body modes, gyroscopic splitting and the stability threshold of
// a spinning top, elimination of redundant constraints, the sparse shift-invert path, sweeps, and the
// YAML and runner wiring.

#include "flexmbd/solver/eigen_analysis.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "case_builders.hpp"
#include "runner_output.hpp"
#include "flexmbd/common/error.hpp"
#include "flexmbd/io/config_loader.hpp"
#include "flexmbd/solver/sparse_system.hpp"
#include "flexmbd/solver/static_solver.hpp"
#include "flexmbd/solver/steady_rotation.hpp"

namespace flexmbd {
namespace eigen_analysis_test {

constexpr double kG = 9.81;  // [m/s^2]

// Linear models (springs, dampers, masses on prismatic joints): K, D and M are exact to round-off and the
// dense eigensolvers are backward stable, so frequencies agree to ~1e-14; 1e-9 leaves a wide margin.
constexpr double kLinearTolerance = 1.0e-9;
// Models whose stiffness comes from constraint forces (pendulums): central differences of the joint forces
// are good to ~4e-11 relative and the multipliers are solved to round-off; 1e-7 leaves a factor of ~1000.
constexpr double kGeometricTolerance = 1.0e-7;
// Steady rotation: the accelerations and multipliers also rest on extrapolated second differences of the
// constraints along the motion (~1e-9 relative); 1e-7 leaves a factor of ~100.
constexpr double kRotatingTolerance = 1.0e-7;

double Hz(double omega) { return omega / (2 * M_PI); }

EigenResult AnalyseInitialState(const ModelSpec& spec, const EigenOptions& options = EigenOptions()) {
  const Model model = BuildModel(spec);
  return EigenAnalysis(model, model.initial_state(), options);
}

std::vector<Mode> ElasticModes(const EigenResult& result) {
  std::vector<Mode> out;
  for (const Mode& m : result.modes) {
    if (!m.rigid_body) out.push_back(m);
  }
  return out;
}

// A body on a prismatic joint along world x, with an optional spring and damper on the joint.
ModelSpec MassOnSlider(double m, double k, double c) {
  ModelSpec spec;
  spec.source = "mass on slider (eigen test)";
  spec.bodies.push_back(test::ArmBody("mass", m, 0.0, 0.01));
  JointSpec joint;
  joint.name = "slider";
  joint.type = JointType::kPrismatic;
  joint.child = "mass";
  joint.axis_J = Vec3::UnitX();
  joint.effects.resize(1);
  if (k > 0) joint.effects[0].springs.push_back({k, 0.0});
  if (c > 0) joint.effects[0].dampers.push_back({c});
  spec.joints.push_back(joint);
  return spec;
}

// The link's x axis turned to -z: a pendulum of test::Pendulum hanging straight down at q = 0.
const Mat3 kDown = AxisAngle(Vec3::UnitY(), M_PI / 2);

ModelSpec HangingPendulum(double m, double arm, double i_cm) {
  ModelSpec spec = test::Pendulum(m, arm, i_cm);
  spec.joints[0].R_PJ = kDown;
  spec.bodies[0].R_WB = kDown;
  return spec;
}

ModelSpec HangingDoublePendulum(double m, double arm, double i_cm) {
  ModelSpec spec = test::DoublePendulum(m, arm, i_cm);
  spec.joints[0].R_PJ = kDown;
  spec.bodies[0].R_WB = kDown;
  spec.bodies[1].R_WB = kDown;
  spec.bodies[1].p_WB = kDown * Vec3(2 * arm, 0, 0);
  return spec;
}

TEST(EigenAnalysis, MassSpringOnPrismaticJointMatchesSqrtKOverM) {
  // Reference: f = sqrt(k/m) / 2 pi; the prismatic joint leaves one degree of freedom.
  const double m = 2.0, k = 50.0;
  const EigenResult result = AnalyseInitialState(MassOnSlider(m, k, 0.0));
  EXPECT_EQ(result.num_dof, 1);
  ASSERT_EQ(result.modes.size(), 1u);
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz(std::sqrt(k / m)), 1.0, kLinearTolerance);
  EXPECT_EQ(result.modes[0].damping_ratio, 0.0);
  EXPECT_FALSE(result.modes[0].rigid_body);
  // The shape is the slide: x of the body and the joint variable, equal.
  const Eigen::VectorXcd& x = result.modes[0].shape;
  EXPECT_NEAR(std::abs(x[0] - x[6]), 0.0, kLinearTolerance);
  EXPECT_NEAR(std::abs(x[0]), 1.0, kLinearTolerance);
}

TEST(EigenAnalysis, DampedMassSpringHasClosedFormDampingRatioAndDampedFrequency) {
  // Reference: zeta = c / (2 sqrt(k m)), f_d = f_n sqrt(1 - zeta^2), f_n = sqrt(k/m) / 2 pi.
  const double m = 2.0, k = 50.0, c = 3.0;
  const EigenResult result = AnalyseInitialState(MassOnSlider(m, k, c));
  ASSERT_EQ(result.modes.size(), 1u);
  const double zeta = c / (2 * std::sqrt(k * m)), f_n = Hz(std::sqrt(k / m));
  EXPECT_FALSE(result.symmetric);
  EXPECT_NEAR(result.modes[0].damping_ratio, zeta, kLinearTolerance);
  EXPECT_NEAR(result.modes[0].frequency_hz / f_n, 1.0, kLinearTolerance);
  EXPECT_NEAR(result.modes[0].damped_frequency_hz / (f_n * std::sqrt(1 - zeta * zeta)), 1.0, kLinearTolerance);
}

TEST(EigenAnalysis, OverdampedMassSpringGivesTwoRealRoots) {
  // Reference: s = (-c +- sqrt(c^2 - 4 k m)) / (2 m) for c > 2 sqrt(k m): two real roots, damping ratio 1 each.
  const double m = 2.0, k = 50.0, c = 40.0;
  const EigenResult result = AnalyseInitialState(MassOnSlider(m, k, c));
  ASSERT_EQ(result.modes.size(), 2u);
  const double root = std::sqrt(c * c - 4 * k * m);
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz((c - root) / (2 * m)), 1.0, kLinearTolerance);
  EXPECT_NEAR(result.modes[1].frequency_hz / Hz((c + root) / (2 * m)), 1.0, kLinearTolerance);
  for (const Mode& mode : result.modes) {
    EXPECT_NEAR(mode.damping_ratio, 1.0, kLinearTolerance);
    EXPECT_EQ(mode.damped_frequency_hz, 0.0);
  }
}

TEST(EigenAnalysis, PhysicalPendulumMatchesSqrtMglOverPivotInertia) {
  // Reference: f = sqrt(m g l / (I_cm + m l^2)) / 2 pi about the hanging equilibrium. The restoring moment
  // comes entirely from the geometric stiffness of the hinge force (the node sits at the centre of mass).
  const double m = 1.5, l = 0.7, i_cm = 0.05;
  const EigenResult result = AnalyseInitialState(HangingPendulum(m, l, i_cm));
  EXPECT_EQ(result.num_dof, 1);
  ASSERT_EQ(result.modes.size(), 1u);
  EXPECT_TRUE(result.symmetric);
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz(std::sqrt(m * kG * l / (i_cm + m * l * l))), 1.0, kGeometricTolerance);
}

TEST(EigenAnalysis, StoredMultipliersOfStaticSolutionGiveSameFrequencyAsConsistentOnes) {
  // Spring pendulum upright at phi = 0 (static_test.cpp): equilibrium k phi = m g l sin(phi) at
  // phi* = 1.8954942670339809 for m g l / k = 2; there V''(phi*) = k - m g l cos(phi*), so
  // f = sqrt((k - m g l cos(phi*)) / (I_cm + m l^2)) / 2 pi. Linearised about SolveStatic's state with its own
  // multipliers (kFromState) and with consistent ones.
  const double m = 2.0, l = 0.5, i_cm = 1.0e-2, k = m * kG * l / 2.0;
  ModelSpec spec = test::Pendulum(m, l, i_cm);
  const Mat3 R_up = AxisAngle(Vec3::UnitY(), -M_PI / 2);
  spec.joints[0].R_PJ = R_up;
  spec.joints[0].effects[0].springs.push_back({k, 0.0});
  spec.joints[0].initial_position = {1.0};
  spec.bodies[0].R_WB = R_up * AxisAngle(Vec3::UnitY(), 1.0);
  spec.solver.load_steps = 1;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  SparseSystem system(model);
  State state = model.initial_state();
  ASSERT_TRUE(SolveStatic(model, &system, &state).converged);
  const double phi = 1.8954942670339809;
  const double expected = Hz(std::sqrt((k - m * kG * l * std::cos(phi)) / (i_cm + m * l * l)));
  for (ReferenceMotion reference : {ReferenceMotion::kFromState, ReferenceMotion::kConsistent}) {
    EigenOptions options;
    options.reference = reference;
    const EigenResult result = EigenAnalysis(model, state, options);
    ASSERT_EQ(result.modes.size(), 1u);
    EXPECT_NEAR(result.modes[0].frequency_hz / expected, 1.0, kGeometricTolerance);
  }
}

TEST(EigenAnalysis, DoublePendulumMatchesLinearisedLagrangeEquations) {
  // Reference, absolute angles t1, t2 of two equal links (mass m, centre of mass at a from their hinge, the
  // second hinged at 2a): M = [I + 5 m a^2, 2 m a^2; 2 m a^2, I + m a^2], K = diag(3 m g a, m g a);
  // det(K - w^2 M) = 0 is a quadratic in w^2.
  const double m = 1.2, a = 0.4, i_cm = 0.03;
  const EigenResult result = AnalyseInitialState(HangingDoublePendulum(m, a, i_cm));
  EXPECT_EQ(result.num_dof, 2);
  ASSERT_EQ(result.modes.size(), 2u);
  const double M11 = i_cm + 5 * m * a * a, M12 = 2 * m * a * a, M22 = i_cm + m * a * a;
  const double K11 = 3 * m * kG * a, K22 = m * kG * a;
  const double c2 = M11 * M22 - M12 * M12, c1 = -(K11 * M22 + K22 * M11), c0 = K11 * K22;
  const double root = std::sqrt(c1 * c1 - 4 * c2 * c0);
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz(std::sqrt((-c1 - root) / (2 * c2))), 1.0, kGeometricTolerance);
  EXPECT_NEAR(result.modes[1].frequency_hz / Hz(std::sqrt((-c1 + root) / (2 * c2))), 1.0, kGeometricTolerance);
}

// Two bodies on prismatic joints in series along x: the first free on the world, the second on the first
// with a spring between them.
ModelSpec FreeSpringPair(double m1, double m2, double k, double c) {
  ModelSpec spec = MassOnSlider(m1, 0.0, 0.0);
  spec.bodies.push_back(test::ArmBody("second", m2, 0.0, 0.01));
  JointSpec joint = spec.joints[0];
  joint.name = "spring_slider";
  joint.parent = "mass";
  joint.child = "second";
  joint.effects[0].springs.push_back({k, 0.0});
  if (c > 0) joint.effects[0].dampers.push_back({c});
  spec.joints.push_back(joint);
  return spec;
}

TEST(EigenAnalysis, FreePairReportsRigidBodyModeAndRelativeMode) {
  // Reference: a free two-mass oscillator has f = 0 (both translate together) and
  // f = sqrt(k (m1 + m2) / (m1 m2)) / 2 pi.
  const double m1 = 1.0, m2 = 3.0, k = 20.0;
  const EigenResult result = AnalyseInitialState(FreeSpringPair(m1, m2, k, 0.0));
  ASSERT_EQ(result.modes.size(), 2u);
  EXPECT_EQ(result.num_rigid_body, 1);
  EXPECT_TRUE(result.modes[0].rigid_body);
  EXPECT_EQ(result.modes[0].frequency_hz, 0.0);
  // Rigid translation: both bodies' x move alike (unknowns 0 and 6), the spring does not stretch.
  const Eigen::VectorXcd& rigid = result.modes[0].shape;
  EXPECT_NEAR(std::abs(rigid[0] - rigid[6]), 0.0, kLinearTolerance);
  EXPECT_NEAR(std::abs(rigid[12 + 1]), 0.0, kLinearTolerance);
  EXPECT_NEAR(result.modes[1].frequency_hz / Hz(std::sqrt(k * (m1 + m2) / (m1 * m2))), 1.0, kLinearTolerance);
}

TEST(EigenAnalysis, DampedFreePairKeepsOneRigidBodyMode) {
  // Reference: with a damper c between the masses the rigid translation stays at s = 0 (one mode) and the
  // relative motion has zeta = c / (2 sqrt(k mu)), mu = m1 m2 / (m1 + m2).
  const double m1 = 1.0, m2 = 3.0, k = 20.0, c = 0.5;
  const EigenResult result = AnalyseInitialState(FreeSpringPair(m1, m2, k, c));
  ASSERT_EQ(result.modes.size(), 2u);
  EXPECT_EQ(result.num_rigid_body, 1);
  const double mu = m1 * m2 / (m1 + m2);
  EXPECT_NEAR(result.modes[1].damping_ratio, c / (2 * std::sqrt(k * mu)), kLinearTolerance);
  EXPECT_NEAR(result.modes[1].frequency_hz / Hz(std::sqrt(k / mu)), 1.0, kLinearTolerance);
}

// A symmetric top (mass m, centre of mass l above the pivot on its symmetry axis z, inertias It, It, Ia about
// the centre of mass) on a spherical joint, spinning at `spin` about the upright axis: a sleeping top.
constexpr double kTopMass = 1.0, kTopArm = 0.1, kTopIt = 0.002, kTopIa = 0.004;

ModelSpec SleepingTop(double spin) {
  ModelSpec spec;
  spec.source = "sleeping top (eigen test)";
  BodySpec top;
  top.name = "top";
  top.mass = kTopMass;
  top.inertia_cm_B = Vec3(kTopIt, kTopIt, kTopIa).asDiagonal();
  top.p_BoBcm_B = Vec3(0, 0, kTopArm);
  top.w_WB_W = Vec3(0, 0, spin);
  spec.bodies.push_back(top);
  JointSpec pivot;
  pivot.name = "pivot";
  pivot.type = JointType::kSpherical;
  pivot.child = "top";
  spec.joints.push_back(pivot);
  spec.solver.gravity = Vec3(0, 0, -kG);
  return spec;
}

// Reference (e.g. Goldstein, Classical Mechanics, sec. 5.7): small tilts u = t_x + i t_y of a sleeping top
// obey It' u'' - i Ia W u' - m g l u = 0, It' = It + m l^2, so u ~ e^{i w t} with
// It' w^2 - Ia W w + m g l = 0, real (stable) iff Ia^2 W^2 > 4 It' m g l. The analysis uses node-frame
// coordinates, turning with the top at W: there the frequencies are |w - W|.
double CriticalSpin() {
  return std::sqrt(4 * (kTopIt + kTopMass * kTopArm * kTopArm) * kTopMass * kG * kTopArm) / kTopIa;
}

TEST(EigenAnalysis, SleepingTopShowsGyroscopicSplitInBodyFrame) {
  const double spin = 100.0, it = kTopIt + kTopMass * kTopArm * kTopArm, mgl = kTopMass * kG * kTopArm;
  const EigenResult result = AnalyseInitialState(SleepingTop(spin));
  EXPECT_EQ(result.num_dof, 3);
  EXPECT_EQ(result.num_rigid_body, 1);  // the spin angle itself
  const std::vector<Mode> elastic = ElasticModes(result);
  ASSERT_EQ(elastic.size(), 2u);
  const double root = std::sqrt(kTopIa * kTopIa * spin * spin - 4 * it * mgl);
  std::vector<double> expected = {std::abs((kTopIa * spin + root) / (2 * it) - spin),
                                  std::abs((kTopIa * spin - root) / (2 * it) - spin)};
  std::sort(expected.begin(), expected.end());
  for (int k = 0; k < 2; ++k) {
    EXPECT_NEAR(elastic[k].frequency_hz / Hz(expected[k]), 1.0, kRotatingTolerance) << "mode " << k;
    EXPECT_NEAR(elastic[k].damping_ratio, 0.0, kRotatingTolerance);
  }
}

TEST(EigenSweep, SleepingTopLosesStabilityBelowCriticalSpin) {
  // Reference: stable iff spin > W_c = sqrt(4 It' m g l) / Ia (see above). The sweep scales the initial spin.
  const double spin = 100.0;
  const Model model = BuildModel(SleepingTop(spin));
  const std::vector<double> factors = {0.8 * CriticalSpin() / spin, 1.2 * CriticalSpin() / spin, 1.0, 1.5};
  const std::vector<SweepPoint> points = EigenSweep(
      model, factors, [&](double f) { return ScaleVelocities(model.initial_state(), f); }, EigenOptions());
  ASSERT_EQ(points.size(), factors.size());
  for (const SweepPoint& p : points) {
    double least = 1.0;
    for (const Mode& mode : p.result.modes) least = std::min(least, mode.damping_ratio);
    if (p.parameter * spin < CriticalSpin()) {
      EXPECT_LT(least, -0.01) << "factor " << p.parameter;  // a root with Re s > 0: flutter
    } else {
      EXPECT_GT(least, -kRotatingTolerance) << "factor " << p.parameter;
    }
  }
  const std::string table = FormatFanPlot(points, "spin_factor", 3);
  EXPECT_EQ(std::count(table.begin(), table.end(), '\n'), 1 + static_cast<long>(factors.size())) << table;
  EXPECT_NE(table.find("spin_factor f1_Hz f2_Hz f3_Hz zeta1"), std::string::npos) << table;
}

TEST(EigenSweep, TrackedModesFollowShapesAcrossACrossing) {
  // Two uncoupled sliders along x and y with stiffnesses 4 and 1 + 5 p (unit masses): their frequencies cross
  // at p = 0.6. Reference: tracked mode k keeps its own slider, so its frequency is sqrt(4) or sqrt(1 + 5 p).
  auto build = [](double p) {
    ModelSpec spec = MassOnSlider(1.0, 4.0, 0.0);
    spec.bodies.push_back(test::ArmBody("other", 1.0, 0.0, 0.01));
    JointSpec joint = spec.joints[0];
    joint.name = "other_slider";
    joint.child = "other";
    joint.axis_J = Vec3::UnitY();
    joint.effects[0].springs[0].stiffness = 1.0 + 5.0 * p;
    spec.joints.push_back(joint);
    SweepCase c{BuildModel(spec), State()};
    c.state = c.model.initial_state();
    return c;
  };
  const std::vector<SweepPoint> points = EigenSweep({0.0, 0.4, 0.8, 1.2}, build, EigenOptions());
  for (const SweepPoint& p : points) {
    ASSERT_EQ(p.result.modes.size(), 2u);
    EXPECT_NEAR(p.result.modes[0].frequency_hz / Hz(std::sqrt(1.0 + 5.0 * p.parameter)), 1.0, kLinearTolerance);
    EXPECT_NEAR(p.result.modes[1].frequency_hz / Hz(2.0), 1.0, kLinearTolerance);
  }
}

// A hub arm of length R turned about the vertical axis at a constant rate by a drive, with a second arm
// hinged about the vertical at its tip (centre of mass a from that hinge), both radial at the start.
constexpr double kHubArm = 0.8, kHubMass = 3.0, kArmMass = 0.7, kArmCm = 0.3, kArmInertia = 0.01;

ModelSpec DrivenHingedArm(double spin) {
  ModelSpec spec;
  spec.source = "driven hub with hinged arm (eigen test)";
  BodySpec hub = test::ArmBody("hub", kHubMass, kHubArm / 2, 0.05);
  hub.w_WB_W = Vec3(0, 0, spin);
  spec.bodies.push_back(hub);
  BodySpec arm = test::ArmBody("arm", kArmMass, kArmCm, kArmInertia);
  arm.p_WB = Vec3(kHubArm, 0, 0);
  arm.w_WB_W = Vec3(0, 0, spin);
  arm.v_WBo_W = Vec3(0, spin * kHubArm, 0);
  spec.bodies.push_back(arm);
  JointSpec drive = test::RevoluteY("spin", "", "hub", Vec3::Zero());
  drive.axis_J = Vec3::UnitZ();
  drive.initial_velocity = {spin};
  // q = spin t for all t near 0: a table through (-1, -spin) and (1e6, 1e6 spin).
  TimeFunctionSpec law;
  law.kind = TimeFunctionSpec::Kind::kTable;
  law.times = {-1.0, 1.0e6};
  law.values = {-spin, 1.0e6 * spin};
  drive.effects[0].drives.push_back(law);
  spec.joints.push_back(drive);
  JointSpec elbow = test::RevoluteY("elbow", "hub", "arm", Vec3(kHubArm, 0, 0));
  elbow.axis_J = Vec3::UnitZ();
  spec.joints.push_back(elbow);
  spec.solver.gravity = Vec3(0, 0, -kG);
  return spec;
}

// Reference: in the frame turning with the hub, the hinged arm is a pendulum in the centrifugal field:
// V = -spin^2 m a R cos(psi) + const, so w = spin sqrt(m a R / (I_cm + m a^2)) (Coriolis terms vanish for one
// degree of freedom; gravity is along the hinges and does no work).
double HingedArmFrequency(double spin) {
  return spin * std::sqrt(kArmMass * kArmCm * kHubArm / (kArmInertia + kArmMass * kArmCm * kArmCm));
}

TEST(EigenAnalysis, DrivenHubShowsCentrifugalStiffeningOfHingedArm) {
  const double spin = 12.0;
  const EigenResult result = AnalyseInitialState(DrivenHingedArm(spin));
  EXPECT_EQ(result.num_dof, 1);
  ASSERT_EQ(result.modes.size(), 1u);
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz(HingedArmFrequency(spin)), 1.0, kRotatingTolerance);
  EXPECT_NEAR(result.modes[0].damping_ratio, 0.0, kRotatingTolerance);
}

TEST(EigenSweep, HingedArmFrequencyIsProportionalToHubSpeed) {
  // Reference as above: w proportional to the spin, which the sweep scales through every initial velocity.
  const double spin = 12.0;
  const Model model = BuildModel(DrivenHingedArm(spin));
  const std::vector<SweepPoint> points = EigenSweep(
      model, {0.25, 0.5, 1.0, 2.0}, [&](double f) { return ScaleVelocities(model.initial_state(), f); },
      EigenOptions());
  for (const SweepPoint& p : points) {
    ASSERT_EQ(p.result.modes.size(), 1u);
    EXPECT_NEAR(p.result.modes[0].frequency_hz / Hz(HingedArmFrequency(p.parameter * spin)), 1.0, kRotatingTolerance);
  }
}

TEST(EigenAnalysis, SteadyRotationOfDrivenHubKeepsTheDriveAndAddsNoRigidMode) {
  // Reference as above. The drive holds the hub in the steady solve and in the modes, so the spin is no degree of
  // freedom and no rigid-body mode is added (docs/theory.md (R2)-(R4)); the arm's radial steady state is the
  // initial state, so the frequency is the one about the initial state.
  const double spin = 12.0;
  const Model model = BuildModel(DrivenHingedArm(spin));
  const SteadyRotation rotation = SteadyRotationOf(model, model.initial_state());
  const SteadyResult steady = SolveSteadyRotation(model, model.initial_state(), rotation);
  const EigenResult result = EigenAnalysisAboutSteadyRotation(model, steady.state, rotation, EigenOptions());
  EXPECT_EQ(result.num_rigid_body, 0);
  ASSERT_EQ(result.modes.size(), 1u);
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz(HingedArmFrequency(spin)), 1.0, kRotatingTolerance);
}

// Parallelogram four-bar hanging from two hinges a distance d apart: equal cranks (length L, centre of mass
// at L/2) and a coupler, all hinged about y. In 3-D its 24 joint rows hold 3 redundant ones.
ModelSpec Parallelogram(double mc, double L, double ic, double mb, double d, double ib) {
  ModelSpec spec;
  spec.source = "parallelogram four-bar (eigen test)";
  for (int k = 0; k < 2; ++k) {
    BodySpec crank = test::ArmBody(k == 0 ? "crank1" : "crank2", mc, L / 2, ic);
    crank.p_WB = Vec3(k * d, 0, 0);
    crank.R_WB = kDown;
    spec.bodies.push_back(crank);
    JointSpec hinge = test::RevoluteY(k == 0 ? "hinge1" : "hinge2", "", crank.name, Vec3(k * d, 0, 0));
    hinge.R_PJ = kDown;
    spec.joints.push_back(hinge);
  }
  BodySpec coupler = test::ArmBody("coupler", mb, d / 2, ib);
  coupler.p_WB = Vec3(0, 0, -L);
  spec.bodies.push_back(coupler);
  for (int k = 0; k < 2; ++k) {
    JointSpec pin = test::RevoluteY(k == 0 ? "pin1" : "pin2", k == 0 ? "crank1" : "crank2", "coupler", Vec3(L, 0, 0));
    pin.R_PJ = kDown.transpose();
    pin.p_CJ = Vec3(k * d, 0, 0);
    spec.joints.push_back(pin);
  }
  spec.solver.gravity = Vec3(0, 0, -kG);
  return spec;
}

TEST(EigenAnalysis, ParallelogramFourBarEliminatesRedundantConstraints) {
  // Reference: the coupler translates on a circle of radius L, so with crank angle phi
  // T = (2 (I_c + m_c L^2/4) + m_b L^2) phi'^2 / 2 and V = (2 m_c g L/2 + m_b g L)(1 - cos phi):
  // w^2 = g (m_c L + m_b L) / (2 (I_c + m_c L^2/4) + m_b L^2). Three of the 24 joint rows are dependent:
  // 3 bodies + 4 variables = 22 unknowns, 1 degree of freedom.
  const double mc = 0.8, L = 0.6, ic = 0.02, mb = 2.0, d = 1.0, ib = 0.3;
  const EigenResult result = AnalyseInitialState(Parallelogram(mc, L, ic, mb, d, ib));
  EXPECT_EQ(result.num_kinematic, 22);
  EXPECT_EQ(result.num_dof, 1);
  ASSERT_EQ(result.modes.size(), 1u);
  const double expected = std::sqrt(kG * (mc * L + mb * L) / (2 * (ic + mc * L * L / 4) + mb * L * L));
  EXPECT_NEAR(result.modes[0].frequency_hz / Hz(expected), 1.0, kGeometricTolerance);
}

TEST(EigenAnalysis, MotionWithoutInertiaIsAClearError) {
  // A point mass (zero inertia) on a spherical joint at its centre of mass can turn without inertia: the
  // reduced mass matrix is singular and the message names a rotation of that body.
  ModelSpec spec;
  spec.source = "point mass on a ball joint (eigen test)";
  spec.bodies.push_back(test::ArmBody("point", 1.0, 0.0, 0.0));
  JointSpec ball;
  ball.name = "ball";
  ball.type = JointType::kSpherical;
  ball.child = "point";
  spec.joints.push_back(ball);
  try {
    AnalyseInitialState(spec);
    FAIL() << "expected a SolverError";
  } catch (const SolverError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("without inertia"), std::string::npos) << what;
    EXPECT_NE(what.find("point rot_"), std::string::npos) << what;
  }
}

// A fixed-free chain of n equal masses on prismatic joints in series along x, equal springs on every joint and,
// if c > 0, equal dampers.
ModelSpec SpringChain(int n, double m, double k, double c) {
  ModelSpec spec;
  spec.source = "spring chain (eigen test)";
  for (int i = 0; i < n; ++i) {
    const std::string name = "m" + std::to_string(i);
    spec.bodies.push_back(test::ArmBody(name, m, 0.0, 0.01));
    JointSpec joint;
    joint.name = "s" + std::to_string(i);
    joint.type = JointType::kPrismatic;
    joint.parent = i == 0 ? "" : "m" + std::to_string(i - 1);
    joint.child = name;
    joint.axis_J = Vec3::UnitX();
    joint.effects.resize(1);
    joint.effects[0].springs.push_back({k, 0.0});
    if (c > 0) joint.effects[0].dampers.push_back({c});
    spec.joints.push_back(joint);
  }
  return spec;
}

TEST(EigenAnalysis, SparseShiftInvertFindsLowestModesOfSpringChain) {
  // Reference: a fixed-free chain of n masses m and springs k has w_j = 2 sqrt(k/m) sin((2j - 1) pi / (2 (2n + 1))).
  const int n = 150;
  const double m = 0.5, k = 200.0;
  EigenOptions options;
  options.method = EigenMethod::kSparse;
  options.num_modes = 6;
  const EigenResult result = AnalyseInitialState(SpringChain(n, m, k, 0.0), options);
  EXPECT_EQ(result.method, "sparse shift-invert");
  ASSERT_EQ(result.modes.size(), 6u);
  for (int j = 1; j <= 6; ++j) {
    const double w = 2 * std::sqrt(k / m) * std::sin((2 * j - 1) * M_PI / (2 * (2 * n + 1)));
    EXPECT_NEAR(result.modes[j - 1].frequency_hz / Hz(w), 1.0, kLinearTolerance) << "mode " << j;
  }
}

TEST(EigenAnalysis, SparseShiftInvertFindsModesNearTargetFrequency) {
  // Reference as above; shifted to mode 11 of 150, the three modes nearest it are 10, 11 and 12.
  const int n = 150;
  const double m = 0.5, k = 200.0;
  auto hz = [&](int j) { return Hz(2 * std::sqrt(k / m) * std::sin((2 * j - 1) * M_PI / (2 * (2 * n + 1)))); };
  EigenOptions options;
  options.method = EigenMethod::kSparse;
  options.num_modes = 3;
  options.shift_hz = hz(11);
  const EigenResult result = AnalyseInitialState(SpringChain(n, m, k, 0.0), options);
  ASSERT_EQ(result.modes.size(), 3u);
  for (int j = 10; j <= 12; ++j) {
    EXPECT_NEAR(result.modes[j - 10].frequency_hz / hz(j), 1.0, kLinearTolerance) << "mode " << j;
  }
}

TEST(EigenAnalysis, SparseShiftInvertMatchesDenseOnDampedFreeChain) {
  // Reference: the dense solution (checked against closed forms above) of a damped chain whose first joint has
  // no spring, so that it also has a rigid-body mode.
  const int n = 70;
  ModelSpec spec = SpringChain(n, 0.5, 200.0, 0.3);
  spec.joints[0].effects[0].springs.clear();
  spec.joints[0].effects[0].dampers.clear();
  EigenOptions dense, sparse;
  dense.method = EigenMethod::kDense;
  sparse.method = EigenMethod::kSparse;
  dense.num_modes = sparse.num_modes = 5;
  const EigenResult a = AnalyseInitialState(spec, dense), b = AnalyseInitialState(spec, sparse);
  EXPECT_EQ(b.method, "sparse shift-invert");
  ASSERT_EQ(a.modes.size(), 5u);
  ASSERT_EQ(b.modes.size(), 5u);
  EXPECT_EQ(a.num_rigid_body, 1);
  EXPECT_TRUE(b.modes[0].rigid_body);
  for (int j = 1; j < 5; ++j) {
    EXPECT_NEAR(b.modes[j].frequency_hz / a.modes[j].frequency_hz, 1.0, kLinearTolerance) << "mode " << j;
    EXPECT_NEAR(b.modes[j].damping_ratio, a.modes[j].damping_ratio, kLinearTolerance) << "mode " << j;
  }
}

TEST(EigenAnalysis, ModeTableListsFrequencyAndDampingPerMode) {
  // Reference: the damped mass-spring above (f_n = sqrt(25)/2 pi = 0.795774715 Hz, zeta = 0.15).
  const std::string table = FormatModeTable(AnalyseInitialState(MassOnSlider(2.0, 50.0, 3.0)));
  EXPECT_NE(table.find("mode  frequency_Hz"), std::string::npos) << table;
  EXPECT_NE(table.find("   1  0.79577472"), std::string::npos) << table;
  EXPECT_NE(table.find("0.15"), std::string::npos) << table;
}

TEST(EigenConfig, SolverEigenBlockIsReadFromYaml) {
  const std::string urdf = std::string(FLEXMBD_SOURCE_DIR) + "/test/data/urdf/pendulum.urdf";
  std::ifstream file(urdf);
  std::stringstream text;
  text << file.rdbuf();
  const ModelSpec spec = LoadModelSpecFromStrings(
      text.str(), "pendulum.urdf",
      YAML::Load("solver: {analysis: eigen, eigen: {modes: 3, static_first: false, sweep: {velocity_scale: [0, 1]}}}"),
      "eigen.yaml");
  EXPECT_EQ(spec.solver.analysis, SolverSpec::Analysis::kEigen);
  EXPECT_EQ(spec.solver.eigen.modes, 3);
  EXPECT_FALSE(spec.solver.eigen.static_first);
  EXPECT_EQ(spec.solver.eigen.sweep_velocity_scale, std::vector<double>({0.0, 1.0}));
  try {
    LoadModelSpecFromStrings(text.str(), "pendulum.urdf",
                             YAML::Load("solver: {analysis: eigen, eigen: {static_first: true, "
                                        "sweep: {velocity_scale: [0, 1]}}}"),
                             "eigen.yaml");
    FAIL() << "expected a ConfigError";
  } catch (const ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("eigen.yaml: solver.eigen.static_first"), std::string::npos) << e.what();
  }
}

TEST(EigenRunner, PrintsModeTableOfUrdfPendulum) {
  // Reference: test/data/urdf/pendulum.urdf, m = 2 kg, l = 0.5 m, I_yy = 0.17 kg m^2 about the centre of mass:
  // f = sqrt(m g l / (I + m l^2)) / 2 pi = 0.609 Hz, linearised about the static equilibrium.
  const std::string table = test::RunnerOutput("test/data/urdf/pendulum.urdf",
                                         "solver: {analysis: eigen, eigen: {static_first: true}}\n", "eigen_runner");
  EXPECT_NEAR(test::TableFrequency(table, 1) / Hz(std::sqrt(2.0 * kG * 0.5 / (0.17 + 2.0 * 0.25))), 1.0,
              test::kPrintedTolerance)
      << table;
}

TEST(EigenRunner, DampedFlexibleAntennaKeepsItsDeploymentModesAtDefaultSettings) {
  // The flexible antenna of bench/ (beams with structural damping 1e-3 s, hinge springs and dampers), its
  // solver block replaced by an eigen-analysis at default settings (dense, 220 degrees of freedom). Reference:
  // the sparse shift-invert solver on the same model, which solves the quadratic problem near zero and keeps
  // the lowest roots to ~1e-10. The dense first-order form spans roots from 0.1 rad/s to the overdamped 4e7
  // rad/s of the stiffest beam modes and keeps the lowest to 3e-6 (measured); 3e-5 is a margin of 10. Before,
  // the two deployment modes (0.016 and 0.027 Hz) were reported as rigid-body modes and the next one 1.4% off.
  std::ifstream file(std::string(FLEXMBD_SOURCE_DIR) + "/bench/antenna_flexible/antenna_flexible.yaml");
  std::stringstream text;
  text << file.rdbuf();
  const std::string yaml = text.str();
  const size_t solver = yaml.find("\nsolver:"), output = yaml.find("\noutput:");
  ASSERT_TRUE(solver != std::string::npos && output != std::string::npos && solver < output);
  const std::string model = yaml.substr(0, solver + 1) + yaml.substr(output + 1);
  const std::string urdf = "config/antenna/antenna.urdf";
  const std::string in_space = "solver: {gravity: [0, 0, 0], analysis: eigen, eigen: {modes: 4";
  const std::string dense = test::RunnerOutput(urdf, model + in_space + "}}\n", "antenna_dense");
  const std::string sparse = test::RunnerOutput(urdf, model + in_space + ", method: sparse}}\n", "antenna_sparse");
  EXPECT_NE(dense.find("(dense): 220 degrees of freedom, 0 rigid-body modes"), std::string::npos) << dense;
  constexpr double kDenseTolerance = 3.0e-5;
  for (int mode = 1; mode <= 4; ++mode) {
    EXPECT_NEAR(test::TableFrequency(dense, mode) / test::TableFrequency(sparse, mode), 1.0, kDenseTolerance)
        << "mode " << mode << "\n" << dense << sparse;
  }
}

}  // namespace eigen_analysis_test
}  // namespace flexmbd
