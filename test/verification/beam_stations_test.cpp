// Station outputs of beams (output.beam_stations; docs/theory.md, "Station outputs").

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "beam_cases.hpp"
#include "flexmbd/solver/simulation.hpp"

namespace flexmbd {
namespace beam_stations_test {

constexpr double kLength = 1.0, kEI = 100.0, kEA = 1.0e4, kGA = 1.0e4, kLoad = 1.0e-3;

TEST(BeamStations, TipLoadGivesShearPAndMomentPTimesArm) {
  // Timoshenko cantilever under a tip load P along y (statics): V2 = P, M3 = P (L - s), the other section
  // forces zero; shear strain P / GA, curvature P (L - s) / EI; deflection P s^2 (3L - s) / (6 EI) + P s / GA.
  // The linear solution (cubic deflection, quadratic rotation) lies in the cubic elements' space and their
  // reduced quadrature integrates its work exactly, so it is reproduced at every s. What is left is the
  // geometric nonlinearity: slopes P L^2 / EI = 1e-5 give section forces within 1e-10 P of the linear ones,
  // but an axial strain of order slope^2 = 1e-10, i.e. an axial force EA 1e-10 = 1e-3 P, which the interpolation
  // between Gauss points carries with an error of a few per mille (2.5e-3 measured): 1e-5 P.
  const std::vector<double> stations = {0.0, 0.3, 0.55, 2.0 / 3.0, kLength};
  ModelSpec spec = test::Cantilever(kLength, 2, 3, test::Section(kEA, kGA, 50.0, kEI, 1.0, 1.0e-3, 1.0e-3));
  spec.loads.push_back(test::TipLoad(LoadSpec::Kind::kForce, Vec3(0, kLoad, 0), kLength));
  spec.output.beam_stations["beam"] = stations;
  spec.solver.analysis = SolverSpec::Analysis::kStatic;
  spec.solver.tol = 1.0e-12;
  const Model model = BuildModel(spec);
  Simulation simulation(model);
  OutputSample last;
  simulation.Run([&](const OutputSample& s) { last = s; });
  ASSERT_EQ(last.beam_stations.size(), stations.size());
  constexpr double kRelativeTolerance = 1.0e-5;
  for (size_t k = 0; k < stations.size(); ++k) {
    const double s = stations[k];
    const BeamStationSample& b = last.beam_stations[k];
    const double M = kLoad * (kLength - s);
    Vec6 load, strain;
    load << 0, kLoad, 0, 0, 0, M;
    strain << 0, kLoad / kGA, 0, 0, 0, M / kEI;
    EXPECT_LT((b.load - load).norm(), kRelativeTolerance * kLoad) << "s = " << s << ": " << b.load.transpose();
    EXPECT_LT((b.strain - strain).norm(), kRelativeTolerance * kLoad * kLength / kEI) << "s = " << s;
    const double deflection = kLoad * s * s * (3 * kLength - s) / (6 * kEI) + kLoad * s / kGA;
    EXPECT_NEAR(b.displacement.y(), deflection, kRelativeTolerance * kLoad * std::pow(kLength, 3) / kEI) << "s = " << s;
    // Rotation about z: the slope of the bending part, P (2 L s - s^2) / (2 EI).
    EXPECT_NEAR(b.rotation.z(), kLoad * (2 * kLength * s - s * s) / (2 * kEI), kRelativeTolerance * kLoad / kEI);
  }
  // The tip station is the tip node.
  const NodeState& tip = simulation.state().nodes[model.beams()[0].nodes.back()];
  const NodeState& tip0 = model.initial_state().nodes[model.beams()[0].nodes.back()];
  EXPECT_LT((last.beam_stations.back().displacement - (tip.x - tip0.x)).norm(), 1.0e-14);
  EXPECT_LT((last.beam_stations.back().rotation - Log(tip.R * tip0.R.transpose())).norm(), 1.0e-14);
}

}  // namespace beam_stations_test
}  // namespace flexmbd
