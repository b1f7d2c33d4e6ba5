// The contact intervals a dynamic run reports (the runner's "stop ...: N contact interval(s)" line) when a contact
// holds at its start: a static analysis (solver.static_first) closed it, so the model's initial state has the stop
// open. The count once started from those initial modes and printed "0 contact interval(s)" for a blade resting on
// its stop in every sample; the contact is one interval from t0, for a rigid stop and an elastic one alike.

#include <gtest/gtest.h>

#include <string>

#include "runner_output.hpp"

namespace flexmbd {
namespace contact_at_start_test {

// hbeam.urdf's blade, 1 m of 2 kg/m in four elements, and the start of its hinge's entry.
constexpr const char* kBladeOnAHinge =
    "beams:\n"
    "  blade: {length: 1.0, elements: 4, damping: 1.0e-4, section: {EA: 1.0e8, GA2: 1.0e7, GA3: 1.0e7, GJ: 1.0e3,"
    " EI2: 1.0e3, EI3: 1.0e3, m: 2.0, m_ii: [1.0e-3, 1.0e-5, 1.0e-5]}}\n"
    "joints:\n"
    "  hinge:\n";

TEST(ContactAtStart, BladeRestingOnItsStopAfterAStaticAnalysisHasOneIntervalFromTheStart) {
  // hbeam.urdf: a flexible blade hinged at its root, resting under gravity on a rigid upper stop at 0 (radius
  // 0.1 m), at rest throughout: the stop force 98.1 N never lets go.
  const std::string yaml = std::string(kBladeOnAHinge) +
      "    backlash: {upper: 0.0, radius_upper: 0.1}\n"
      "solver: {t_end: 0.5, static_first: true}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "contact_at_start");
  EXPECT_NE(out.find("stop hinge upper: 1 contact interval(s) [0, 0.5] s"), std::string::npos) << out;
}

TEST(ContactAtStart, BladeRestingOnAnElasticStopAfterAStaticAnalysisHasOneIntervalFromTheStart) {
  // The blade above on a Hertz stop (k 1e6 N/m^1.5), started 0.01 rad off it: the equilibrium presses it with 98.1 N
  // (an approach of 2.1e-3 m), which never lets go. Its interval once opened at the end of the first step ([0.01,
  // 0.5] s), as only a step committed an elastic contact.
  const std::string yaml = std::string(kBladeOnAHinge) +
      "    initial: {position: -0.01}\n"
      "    backlash: {upper: 0.0, radius_upper: 0.1, stop: {type: elastic, law: hertz, stiffness: 1.0e6,"
      " restitution: 0.7}}\n"
      "solver: {t_end: 0.5, static_first: true}\n";
  const std::string out = test::RunnerOutput("test/data/urdf/hbeam.urdf", yaml, "elastic_contact_at_start");
  EXPECT_NE(out.find("stop hinge upper: 1 contact interval(s) [0, 0.5] s"), std::string::npos) << out;
}

}  // namespace contact_at_start_test
}  // namespace flexmbd
