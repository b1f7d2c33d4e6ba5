// ~contacts on the pendulum-stop case (config/pendulum_stop/, run to 5 s by
// test/integration/data/long_pendulum_stop.yaml): a 2 kg, 1 m rod released horizontal falls 60 deg onto an
// elastic Hertz stop (5e6 N/m^1.5, e = 0.7) 0.1 m from the hinge, bounces and comes to rest on it.

#include <gtest/gtest.h>

#include <cmath>

#include "helpers/csv_table.hpp"
#include "helpers/recorded_run_suite.hpp"

namespace flexmbd {
namespace test {
namespace effect_contacts_test {

constexpr char kNodeName[] = "flexmbd_contacts";
constexpr char kUrdf[] = "config/pendulum_stop/pendulum_stop.urdf";
constexpr char kConfig[] = "test/integration/data/long_pendulum_stop.yaml";
constexpr double kEndTime = 5.0;
// The rod (pendulum_stop.urdf): mass, centre of mass from the hinge, inertia about the hinge; the stop.
constexpr double kMass = 2.0, kArm = 0.5, kInertia = 0.16667 + kMass * kArm * kArm, kG = 9.81;
constexpr double kStopAngle = 1.0472, kRadius = 0.1, kStiffness = 5.0e6, kExponent = 1.5;
// Same run, same steps: the node's records equal the runner's CSV to its 17 digits.
constexpr double kSameRunTolerance = 1.0e-9;

class EffectContacts : public RecordedRunSuite<EffectContacts> {
 public:
  static constexpr char kAwaited[] = "~contacts";
  static NodeRunCase Case() {
    return {kNodeName, kUrdf, kConfig, /*record_bag=*/false, ReachesEnd(&Samples::contacts, kEndTime)};
  }

 protected:
  // The droop stop's record in a message (the URDF <limit> gives stops "lower" and "upper"; upper is 60 deg).
  static const JointContact& Droop(const JointContactArray& message) {
    for (const JointContact& c : message.contacts) {
      if (c.joint == "hinge" && c.stop == "upper") return c;
    }
    throw std::runtime_error("no stop hinge/upper in ~contacts");
  }
};

TEST_F(EffectContacts, ImpactsHappenWithForcesBetweenRestAndTheElasticPeak) {
  // Released from rest, the rod meets the stop at w^2 = 2 m g a sin(60 deg) / I; the contact point then
  // moves at v = rho w against an effective mass I / rho^2. A lossless Hertz contact would peak at
  // F = k a_max^n with a_max = ((n + 1) m_eff v^2 / (2 k))^(1 / (n + 1)); the Hunt-Crossley damping of e < 1
  // lowers the rebound, and 200 samples per second see the first contact somewhere below its peak.
  const double w = std::sqrt(2 * kMass * kG * kArm * std::sin(kStopAngle) / kInertia);
  const double v = kRadius * w, m_eff = kInertia / (kRadius * kRadius);
  const double a_max = std::pow((kExponent + 1) * m_eff * v * v / (2 * kStiffness), 1 / (kExponent + 1));
  const double elastic_peak = kStiffness * std::pow(a_max, kExponent);
  const double resting = kMass * kG * kArm * std::cos(kStopAngle) / kRadius;
  int contacts = 0;
  bool before = false;
  double first_peak = 0;
  for (const JointContactArray& message : record_->topics.contacts) {
    const JointContact& c = Droop(message);
    if (c.in_contact && !before) ++contacts;
    if (c.in_contact && contacts == 1) first_peak = std::max(first_peak, c.force);
    before = c.in_contact;
    EXPECT_NEAR(c.torque, -kRadius * c.force, 1e-12 * (1 + c.force)) << "an upper stop pushes q down";
  }
  EXPECT_GE(contacts, 3) << "the rod bounces on the stop";
  EXPECT_GT(first_peak, resting);
  // The Hunt-Crossley force at a given approach exceeds the elastic one while approaching: 20% above the
  // lossless peak bounds it for e = 0.7 at this speed.
  EXPECT_LT(first_peak, 1.2 * elastic_peak);
}

TEST_F(EffectContacts, RodComesToRestOnTheStop) {
  // At rest the stop carries the gravity moment through its radius at the angle where its approach
  // a = (F / k)^(1/n) puts the rod: F = m g a cos(60 deg + a / rho) / rho, solved by fixed-point iteration
  // (a contraction: dF/dF ~ 1e-2). The last bounce has died out by 5 s to below 1e-6 of F: 1e-4.
  double force = kMass * kG * kArm * std::cos(kStopAngle) / kRadius;
  for (int k = 0; k < 50; ++k) {
    const double approach = std::pow(force / kStiffness, 1 / kExponent);
    force = kMass * kG * kArm * std::cos(kStopAngle + approach / kRadius) / kRadius;
  }
  constexpr double kRestTolerance = 1.0e-4;
  const JointContact& last = Droop(record_->topics.contacts.back());
  EXPECT_TRUE(last.in_contact);
  EXPECT_NEAR(last.force, force, kRestTolerance * force);
  EXPECT_NEAR(last.approach, std::pow(force / kStiffness, 1 / kExponent), kRestTolerance * last.approach);
}

TEST_F(EffectContacts, RecordsMatchTheRunnersCsv) {
  const CsvTable& csv = record_->csv;
  const std::vector<JointContactArray>& contacts = record_->topics.contacts;
  ASSERT_EQ(csv.rows.size(), contacts.size()) << "the runner did not write its CSV";
  for (size_t k = 0; k < contacts.size(); ++k) {
    const std::vector<double>& row = csv.rows[k];
    const JointContact& c = Droop(contacts[k]);
    EXPECT_EQ(c.in_contact, row[csv.Column("stop.hinge.upper.in_contact")] != 0) << "t = " << row[0];
    EXPECT_NEAR(c.force, row[csv.Column("stop.hinge.upper.force")], kSameRunTolerance * (1 + c.force));
    EXPECT_NEAR(c.approach, row[csv.Column("stop.hinge.upper.approach")], kSameRunTolerance);
  }
}

}  // namespace effect_contacts_test
}  // namespace test
}  // namespace flexmbd
