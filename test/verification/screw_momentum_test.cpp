// A nut falling on a screw whose shaft turns freely, run the user's way (flexmbd_run on YAML): the screw joint
// passes the torque that the pitch couples to the nut's fall to the shaft, and angular momentum about the axis
// stays zero. Under the energy-consistent schemes the torques on the shaft and on the nut came from discrete
// gradients that did not balance: the shaft ended at 1.5133 rad instead of 1.5566, H_z at -2.0e-3 (7% of the
// shaft's), and a held shaft's holding torque drifted by -9.7% (docs/theory.md, "Angular momentum of joint
// torques").

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "../integration/helpers/csv_table.hpp"
#include "runner_output.hpp"

namespace flexmbd {
namespace screw_momentum_test {

constexpr double kG = 9.81, kMass = 2.0, kShaftJ = 0.01, kNutJ = 0.002;
const double kLead = 0.01 / (2.0 * M_PI);  // pitch 0.01 m per turn: m per rad

// The fall is a constant acceleration, which the trapezoidal rule of both schemes integrates exactly (the
// energy-decaying term alpha h (a - a_prev) vanishes), so the positions are exact to the Newton tolerance of the
// rows, relative 1e-10 here (measured 2e-12); the runs before the mend were off by 2.8%.
constexpr double kExact = 1.0e-9;

// The runner's table of every accepted step of `yaml_text` (solver and closures) on a nut_on_free_screw URDF.
test::CsvTable Steps(const std::string& urdf, const std::string& yaml_text, const std::string& name) {
  const std::string path = testing::TempDir() + name + ".csv";
  test::RunnerOutput("test/data/urdf/" + urdf, yaml_text + "output: {rate_hz: 0, csv: " + path + "}\n", name);
  return test::ReadCsv(path);
}

// Shaft angle at time t: the nut's fall c phi'' = -a with a = g m c^2 / (J_s J_n / (J_s + J_n) + m c^2) turns
// the screw by phi = -a t^2 / (2 c), and H_z = J_s w_s + J_n (w_s + phi') = 0 turns the shaft by
// -phi J_n / (J_s + J_n).
double ShaftAngle(double t) {
  const double reduced = kShaftJ * kNutJ / (kShaftJ + kNutJ);
  const double a = kG * kMass * kLead * kLead / (reduced + kMass * kLead * kLead);
  const double phi = -0.5 * a * t * t / kLead;
  return -phi * kNutJ / (kShaftJ + kNutJ);
}

void ExpectMomentumKeptAndClosedForm(const test::CsvTable& csv, const std::string& run) {
  ASSERT_GT(csv.rows.size(), 3u) << run;
  const size_t shaft = csv.Column("joint.bearing.position"), shaft_rate = csv.Column("joint.bearing.velocity");
  const size_t screw_rate = csv.Column("joint.lead.velocity");
  // H_z scale: the nut's angular momentum at the end, J_n |phi'| = 0.002 x 18.7 = 0.037 N m s.
  const double scale = kNutJ * std::abs(csv.rows.back()[screw_rate]);
  for (const std::vector<double>& row : csv.rows) {
    const double t = row[0];
    EXPECT_NEAR(row[shaft], ShaftAngle(t), kExact * ShaftAngle(1.0)) << run << " t = " << t;
    const double H = kShaftJ * row[shaft_rate] + kNutJ * (row[shaft_rate] + row[screw_rate]);
    EXPECT_NEAR(H, 0.0, kExact * scale) << run << " t = " << t;
  }
  EXPECT_NEAR(csv.rows.back()[0], 1.0, 1.0e-12) << run;
}

TEST(ScrewMomentum, NutFallingOnAFreeShaftKeepsAngularMomentumAndTheClosedForm) {
  for (const char* integrator : {"energy_decaying", "energy_preserving"}) {
    const std::string solver =
        std::string("solver: {t_end: 1.0, dt: 1.0e-3, integrator: ") + integrator + "}\n";
    ExpectMomentumKeptAndClosedForm(
        Steps("nut_on_free_screw.urdf", "joints: {lead: {type: screw, pitch: 0.01}}\n" + solver,
              std::string("screw_tree_") + integrator),
        std::string("tree, ") + integrator);
    ExpectMomentumKeptAndClosedForm(
        Steps("floating_nut_on_free_screw.urdf",
              "closures: {lead: {type: screw, parent: shaft, child: nut, axis: [0, 0, 1], pitch: 0.01}}\n" + solver,
              std::string("screw_closure_") + integrator),
        std::string("closure, ") + integrator);
  }
}

TEST(ScrewMomentum, HeldShaftCarriesTheNutsTorqueThroughout) {
  // The shaft held (bearing driven at 0): the nut falls with a = g m c^2 / (J_n + m c^2) and turns at
  // phi'' = -a / c, so the shaft holds J_n a / c = 0.031147 N m against it at every step, which the drive reports
  // as the bearing's effort: -J_n a / c.
  const double a = kG * kMass * kLead * kLead / (kNutJ + kMass * kLead * kLead);
  const double holding = -kNutJ * a / kLead;
  for (const char* integrator : {"energy_decaying", "energy_preserving"}) {
    const test::CsvTable csv = Steps("nut_on_free_screw.urdf",
                                     "joints: {bearing: {drive: {law: constant, value: 0.0}},\n"
                                     "         lead: {type: screw, pitch: 0.01}}\n"
                                     "solver: {t_end: 1.0, dt: 1.0e-3, integrator: " +
                                         std::string(integrator) + "}\n",
                                     std::string("held_shaft_") + integrator);
    ASSERT_GT(csv.rows.size(), 3u) << integrator;
    const size_t effort = csv.Column("joint.bearing.effort");
    // The drive's multiplier is a force of the step, exact like the motion: the Newton tolerance again.
    for (size_t k = 1; k < csv.rows.size(); ++k) {
      EXPECT_NEAR(csv.rows[k][effort], holding, kExact * std::abs(holding)) << integrator << " t = " << csv.rows[k][0];
    }
  }
}

}  // namespace screw_momentum_test
}  // namespace flexmbd
