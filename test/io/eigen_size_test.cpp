// The bound on a dense eigen-analysis (include/flexmbd/model/eigen_size.hpp, docs/config.md "solver.eigen"):
// method: dense above kMaxDenseEigenUnknowns kinematic unknowns is a ConfigError naming the field; auto and
// sparse are not bounded. Found by the fuzzer: a 200,000-element beam asking for a dense analysis.

#include <gtest/gtest.h>

#include <string>

#include "flexmbd/model/eigen_size.hpp"
#include "io_test_util.hpp"

namespace flexmbd {
namespace eigen_size_test {
using test::LoadDataUrdf;

// The beam arm of test/data with its element count and eigen settings replaced: 6 (3 elements + 1) unknowns
// of the beam's nodes, plus the tip body's 6 and its hinge's 1.
Model BeamArm(int elements, const std::string& method) {
  const std::string yaml = "beams:\n  arm:\n    length: 1.0\n    elements: " + std::to_string(elements) +
                           "\n    order: 3\n    section: {EA: 1.0e7, GA2: 4.0e6, GA3: 4.0e6, GJ: 50.0, EI2: 80.0, "
                           "EI3: 100.0, m: 2.5, m_ii: [0.002, 0.001, 0.001]}\n"
                           "solver: {analysis: eigen, eigen: {modes: 4, method: " + method + "}}\n";
  return BuildModel(LoadDataUrdf("beam_arm.urdf", yaml, "beam_arm.yaml"));
}

TEST(EigenSize, DenseAboveTheBoundIsRejectedNamingTheField) {
  // 300 cubic elements: 901 beam nodes, 5,413 kinematic unknowns, above 5,000.
  EXPECT_CONFIG_ERROR(BeamArm(300, "dense"), "beam_arm.urdf + beam_arm.yaml: solver.eigen.method: dense for ");
  EXPECT_CONFIG_ERROR(BeamArm(300, "dense"), "more than 5000");
  EXPECT_CONFIG_ERROR(BeamArm(300, "dense"), "expected method: sparse (the lowest modes by shift-invert) or auto");
}

TEST(EigenSize, BelowTheBoundAndOtherMethodsLoad) {
  // 250 cubic elements: 751 beam nodes, 4,513 kinematic unknowns.
  EXPECT_NO_THROW(BeamArm(250, "dense"));
  EXPECT_NO_THROW(BeamArm(300, "sparse"));
  EXPECT_NO_THROW(BeamArm(300, "auto"));
}

}  // namespace eigen_size_test
}  // namespace flexmbd
