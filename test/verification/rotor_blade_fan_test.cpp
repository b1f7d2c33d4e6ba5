// The fan plot of one blade of the rotor engage model (issue 18; config/rotor_engage/blade_fan.yaml, docs/cases.md)
// through the runner: the first flap and torsion frequencies over rotor speed, each speed about its own steady
// rotation, against the closed forms of a rigid articulated blade in flap and a uniform blade in torsion.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "runner_output.hpp"

namespace flexmbd {
namespace rotor_blade_fan_test {

constexpr double kOmega0 = 27.61;  // rad/s, the hub's initial rate in blade_fan.yaml
const double kFactors[] = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.1, 1.2};
constexpr int kFlapColumn = 1;     // after the spin (column 0, a rigid-body mode at 0 Hz)
constexpr int kTorsionColumn = 5;  // checked below against the clamped rod's frequency

// The flapping parts about the flap hinge (blade_fan.urdf, the data of rotor_engage.yaml): yoke 5 kg at 0.075 m,
// grip 10 kg at 0.25 m, blade 11 kg/m from 0.35 to 7.47 m; hinge offset e = 0.30 m. Their own inertias in the
// blade's axes (x radial, y the hinge axis, z normal): yoke 0.01 about each; grip 0.02, 0.05, 0.05; blade section
// m_ii = (0.17, 0.002, 0.168) kg m over 7.12 m.
constexpr double kOffset = 0.30, kBladeMass = 11.0, kBladeRoot = 0.35, kBladeTip = 7.47, kBladeLength = 7.12;
constexpr double kSectionInertia[] = {0.17, 0.002, 0.168};

// Rigid flap about an offset hinge: I_yy beta'' + Omega^2 (I_zz - I_xx + e S) beta = 0, with S and the inertias
// about the hinge (the rotating frame's centrifugal moment of the turned body; for a slender blade the classical
// nu^2 = 1 + e S / I).
double RigidFlapPerRev() {
  const double second = 5.0 * 0.075 * 0.075 + 10.0 * 0.25 * 0.25 +
                        kBladeMass * (std::pow(kBladeTip, 3) - std::pow(kBladeRoot, 3)) / 3.0;
  const double first = 5.0 * 0.075 + 10.0 * 0.25 + kBladeMass * (kBladeTip * kBladeTip - kBladeRoot * kBladeRoot) / 2.0;
  const double own_zz_minus_xx = (0.05 - 0.02) + (kSectionInertia[2] - kSectionInertia[0]) * kBladeLength;
  const double own_yy = 0.01 + 0.05 + kSectionInertia[1] * kBladeLength;
  return std::sqrt((second + own_zz_minus_xx + kOffset * first) / (second + own_yy));
}
// The rigid blade's straight shape is a Rayleigh trial shape of the flexible blade's first flap mode, so the
// closed form bounds it from above (to the printed 8 digits); the hinge offset's centrifugal load, which a straight
// blade does not balance, bends it by a share ~ (e S / I)^2 (Omega / omega_2)^2 / 2 = 0.0607^2 x 0.12 / 2 = 2.2e-4
// at 1.2 Omega_0 (omega_2 the second flap mode, 3.05 per rev at Omega_0). Measured 1.3e-6 (0.1 Omega_0) to 5.4e-5
// (1.2 Omega_0) below.
constexpr double kPrinted = 1.0e-7, kElasticFlap = 2.5e-4;

// Torsion of a uniform blade spun in its plane: the propeller moment adds Omega^2 (m_zz - m_yy) per length to the
// torsional stiffness, and the section inertia m_xx resists, so omega_T^2(Omega) = omega_T^2(0) + Omega^2 (m_zz -
// m_yy) / m_xx = omega_T^2(0) + 0.97647 Omega^2 whatever the mode's shape, the added stiffness being proportional to
// the torsional inertia (the grip, 0.02 kg m^2 with no propeller moment at the root where the stiff pitch spring
// leaves the mode 2% of its tip twist, departs from it by ~1e-5). Flap and torsion do not couple (m_xx = m_yy +
// m_zz: the gyroscopic coupling Omega (m_yy + m_zz - m_xx) vanishes; centre of mass on the beam axis).
constexpr double kPropellerRatio = (kSectionInertia[2] - kSectionInertia[1]) / kSectionInertia[0];
// From 0.5 Omega_0 on, the rise of omega_T^2 (186 to 1070 rad^2/s^2 on 42,000) is read from 8 printed digits to
// 2e-6; 1e-3 leaves room for the grip. Measured 2.7e-6 at Omega_0, 3.5e-5 at 1.2 Omega_0.
constexpr double kPropellerTolerance = 1.0e-3;
// The torsion column at rest against the clamped uniform rod, (pi / 2) sqrt(GJ / m_xx) / L = 32.98 Hz: the pitch
// spring (EA a^2 / L = 1.6e6 N m/rad against GJ / L = 2.1e4) and the grip lower it by a few percent (measured 1.3%).
constexpr double kClampedRodTolerance = 0.05;

std::string FanOutput() {
  std::ifstream in(std::string(FLEXMBD_SOURCE_DIR) + "/config/rotor_engage/blade_fan.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  yaml = yaml.substr(0, yaml.find("\noutput:") + 1);  // no CSV file from the test
  return test::RunnerOutput("config/rotor_engage/blade_fan.urdf", yaml, "rotor_blade_fan");
}

double PerRev(double hz, double factor) { return 2.0 * M_PI * hz / (factor * kOmega0); }

TEST(RotorBladeFan, FirstFlapIsTheRigidArticulatedBladesJustBelowIt) {
  const std::string output = FanOutput();
  const double rigid = RigidFlapPerRev();  // 1.029860 per rev
  for (double factor : kFactors) {
    const std::vector<double> row = test::FanRow(output, factor);
    ASSERT_GT(row.size(), static_cast<size_t>(kTorsionColumn)) << "factor " << factor << "\n" << output;
    EXPECT_EQ(row[0], 0.0) << "the spin, a rigid-body mode; factor " << factor;
    const double flap = PerRev(row[kFlapColumn], factor);
    EXPECT_LE(flap, rigid * (1 + kPrinted)) << "factor " << factor;
    EXPECT_GE(flap, rigid * (1 - kElasticFlap)) << "factor " << factor;
  }
}

TEST(RotorBladeFan, TorsionStiffensByThePropellerMoment) {
  const std::string output = FanOutput();
  const std::vector<double> rest = test::FanRow(output, 0.0);
  ASSERT_GT(rest.size(), static_cast<size_t>(kTorsionColumn)) << output;
  const double clamped_rod_hz = M_PI / 2 * std::sqrt(1.5e5 / kSectionInertia[0]) / kBladeLength / (2 * M_PI);
  EXPECT_NEAR(rest[kTorsionColumn] / clamped_rod_hz, 1.0, kClampedRodTolerance) << output;
  const double rest_squared = std::pow(2 * M_PI * rest[kTorsionColumn], 2);
  for (double factor : kFactors) {
    if (factor < 0.5) continue;
    const std::vector<double> row = test::FanRow(output, factor);
    ASSERT_GT(row.size(), static_cast<size_t>(kTorsionColumn)) << "factor " << factor;
    const double omega = factor * kOmega0;
    const double ratio = (std::pow(2 * M_PI * row[kTorsionColumn], 2) - rest_squared) / (omega * omega);
    EXPECT_NEAR(ratio / kPropellerRatio, 1.0, kPropellerTolerance) << "factor " << factor;
  }
}

}  // namespace rotor_blade_fan_test
}  // namespace flexmbd
