// Large-deflection statics of the geometrically exact beam against closed forms.

#include <gtest/gtest.h>

#include <cmath>

#include "../integration/helpers/csv_table.hpp"
#include "beam_cases.hpp"
#include "flexmbd/solver/simulation.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace beam_static_test {

constexpr double kLength = 1.0, kEI = 100.0;
// Axial and shear stiffness 1e6 times EI / L^2 make the beam practically inextensible and shear-rigid, as the
// closed forms assume: their effect on the tip position is ~1e-6 L.
const BeamSectionSpec kSection = test::Section(1.0e8, 1.0e8, kEI, kEI, 1.0, 1.0e-3, 1.0e-3);

Vec3 StaticTip(ModelSpec spec, int load_steps) {
  spec.solver.analysis = SolverSpec::Analysis::kStatic;
  spec.solver.load_steps = load_steps;
  // Force residuals of this stiff section are round-off limited near 1e-9 relative (EA/EI = 1e6).
  spec.solver.tol = 1.0e-8;
  spec.solver.max_iterations = 40;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  simulation.Run([](const OutputSample&) {});
  return simulation.state().nodes[model.beams()[0].nodes.back()].x;
}

TEST(BeamStatics, TipMomentTwoPiEIOverLRollsIntoFullCircle) {
  // Pure bending: curvature M/EI = 2 pi / L, so the beam closes a circle and the tip returns to the root.
  ModelSpec spec = test::Cantilever(kLength, 8, 3, kSection);
  spec.loads.push_back(test::TipLoad(LoadSpec::Kind::kMoment, Vec3(0, 0, 2 * M_PI * kEI / kLength), kLength));
  const Vec3 tip = StaticTip(spec, 20);
  // The criterion: back at the root to 1e-3 L.
  constexpr double kClosure = 1.0e-3;
  EXPECT_LT(tip.norm(), kClosure * kLength) << tip.transpose();
}

TEST(BeamStatics, TipMomentPiEIOverLMakesHalfCircle) {
  // Radius L / pi: the tip ends at (0, 2 L / pi, 0).
  ModelSpec spec = test::Cantilever(kLength, 8, 3, kSection);
  spec.loads.push_back(test::TipLoad(LoadSpec::Kind::kMoment, Vec3(0, 0, M_PI * kEI / kLength), kLength));
  const Vec3 tip = StaticTip(spec, 10);
  // Cubic elements represent the arc to ~1e-6 L with 8 elements; 1e-4 L leaves room for the finite EA.
  constexpr double kTolerance = 1.0e-4;
  EXPECT_NEAR(tip.x(), 0.0, kTolerance * kLength);
  EXPECT_NEAR(tip.y(), 2.0 * kLength / M_PI, kTolerance * kLength);
  EXPECT_NEAR(tip.z(), 0.0, kTolerance * kLength);
}

TEST(BeamStatics, TipMomentFromYamlAtDefaultSettingsMakesHalfCircle) {
  // As a user writes it, through the runner at the default solver settings: the moment's point picks the tip node
  // (docs/config.md, loads[]). The tip moves from (L, 0, 0) to (0, 2 L / pi, 0), with the curvature pi / L
  // and the moment pi EI / L all along (its rotation, pi, lies on the rotation vector's branch cut).
  const std::string csv = testing::TempDir() + "tip_moment_half_circle.csv";
  const std::string yaml =
      "beams: {arm: {length: 1.0, elements: 8, section: {EA: 1.0e8, GA2: 1.0e8, GA3: 1.0e8, GJ: 100.0, EI2: 100.0,\n"
      "        EI3: 100.0, m: 1.0, m_ii: [1.0e-3, 1.0e-3, 1.0e-3]}}}\n"
      "loads: [{body: arm, moment: [0.0, 0.0, 314.1592653589793], point: [1.0, 0.0, 0.0]}]\n"
      "solver: {analysis: static, gravity: [0.0, 0.0, 0.0]}\n"
      "output: {csv: " + csv + ", beam_stations: {arm: [1.0]}}\n";
  test::RunnerOutput("test/data/urdf/cantilever.urdf", yaml, "tip_moment_half_circle");
  const test::CsvTable table = test::ReadCsv(csv);
  ASSERT_EQ(table.rows.size(), 1u);
  const std::vector<double>& tip = table.rows.back();
  // As TipMomentPiEIOverLMakesHalfCircle: cubic elements represent the arc to ~1e-6 L, the finite EA adds ~1e-6 L;
  // Newton's default tol (1e-6, relative) leaves less.
  constexpr double kTolerance = 1.0e-4;
  EXPECT_NEAR(tip[table.Column("beam.arm.s0.ux")], -kLength, kTolerance * kLength);
  EXPECT_NEAR(tip[table.Column("beam.arm.s0.uy")], 2.0 * kLength / M_PI, kTolerance * kLength);
  EXPECT_NEAR(tip[table.Column("beam.arm.s0.uz")], 0.0, kTolerance * kLength);
  EXPECT_NEAR(tip[table.Column("beam.arm.s0.k3")], M_PI / kLength, kTolerance * M_PI / kLength);
  EXPECT_NEAR(tip[table.Column("beam.arm.s0.M3")], M_PI * kEI / kLength, kTolerance * M_PI * kEI / kLength);
}

// Inextensible, shear-rigid elastica of a cantilever (L = EI = 1) under a dead tip load k across the beam:
// theta'' = -k cos(theta), theta(0) = 0, theta'(1) = 0. Solved by shooting on theta'(0) with classical RK4;
// returns the tip displacement along the beam (towards the root) and across it. 4000 steps give 1e-12.
Eigen::Vector2d ElasticaTip(double k) {
  auto integrate = [k](double slope, Eigen::Vector4d* end) {
    constexpr int kSteps = 4000;
    const double h = 1.0 / kSteps;
    auto f = [k](const Eigen::Vector4d& y) {
      return Eigen::Vector4d(y[1], -k * std::cos(y[0]), std::cos(y[0]), std::sin(y[0]));
    };
    Eigen::Vector4d y(0.0, slope, 0.0, 0.0);
    for (int i = 0; i < kSteps; ++i) {
      const Eigen::Vector4d k1 = f(y), k2 = f(y + 0.5 * h * k1), k3 = f(y + 0.5 * h * k2), k4 = f(y + h * k3);
      y += h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
    }
    *end = y;
  };
  double lo = 0.0, hi = k;  // theta'(0) is between 0 and the linear value k
  Eigen::Vector4d end;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    integrate(mid, &end);
    (end[1] > 0.0 ? hi : lo) = mid;
  }
  integrate(0.5 * (lo + hi), &end);
  return Eigen::Vector2d(1.0 - end[2], end[3]);
}

TEST(BeamStatics, TipLoadMatchesElasticaDeflections) {
  // Cantilever under a dead transverse tip load, k = P L^2 / EI = 1, 2, 5, 10, against the elastica (elliptic
  // integral solution, computed here by shooting; for k = 1, 2, 5 it reproduces Mattiasson, IJNME 17 (1981),
  // Table I, e.g. k = 5: 0.38763 L and 0.71379 L).
  for (double k : {1.0, 2.0, 5.0, 10.0}) {
    ModelSpec spec = test::Cantilever(kLength, 8, 3, kSection);
    spec.loads.push_back(test::TipLoad(LoadSpec::Kind::kForce, Vec3(0, -k * kEI / (kLength * kLength), 0), kLength));
    const Vec3 tip = StaticTip(spec, 10);
    const Eigen::Vector2d exact = ElasticaTip(k);
    // Cubic elements: discretisation ~1e-6 L; finite EA and GA: P / EA ~ 1e-5 at k = 10.
    constexpr double kTolerance = 2.0e-5;
    EXPECT_NEAR((kLength - tip.x()) / kLength, exact[0], kTolerance) << "k = " << k;
    EXPECT_NEAR(-tip.y() / kLength, exact[1], kTolerance) << "k = " << k;
  }
}

}  // namespace beam_static_test
}  // namespace flexmbd
