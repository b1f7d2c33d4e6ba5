#include "flexmbd/model/beam_layout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/Eigenvalues>

#include "flexmbd/common/error.hpp"
#include "flexmbd/common/number_text.hpp"

namespace flexmbd {
namespace {
// Stations closer than this fraction of the beam length are the same point (round-off of URDF origins).
constexpr double kStationTolerance = 1.0e-9;

// Most node positions a message lists; a longer beam's are given by their spacing.
constexpr size_t kListedNodes = 12;

// Integral over [-1, 1] of the Lagrange shape function of node k (equally spaced nodes), by Gauss-Legendre
// with enough points to be exact for its degree.
double ShapeIntegral(int order, int k) {
  static const double kPoints[] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                   0.8611363115940526};
  static const double kWeights[] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                    0.3478548451374538};
  double integral = 0.0;
  for (int g = 0; g < 4; ++g) {
    double N = 1.0;
    for (int j = 0; j <= order; ++j) {
      if (j == k) continue;
      const double xi_j = -1.0 + 2.0 * j / order, xi_k = -1.0 + 2.0 * k / order;
      N *= (kPoints[g] - xi_j) / (xi_k - xi_j);
    }
    integral += kWeights[g] * N;
  }
  return integral;
}
}  // namespace

std::vector<double> BeamStations(const BeamSpec& beam) {
  const int n = beam.elements * beam.order + 1;
  std::vector<double> s(n);
  for (int k = 0; k < n; ++k) s[k] = beam.length * k / (n - 1);
  return s;
}

std::vector<NodeState> BeamNodeStates(const BeamSpec& beam) {
  std::vector<NodeState> nodes;
  for (double s : BeamStations(beam)) {
    NodeState n;
    const Vec3 r = beam.R_WB * Vec3(s, 0, 0);
    n.x = beam.p_WB + r;
    n.R = beam.R_WB;
    n.v = beam.v_WBo_W + beam.w_WB_W.cross(r);
    n.w = beam.R_WB.transpose() * beam.w_WB_W;
    nodes.push_back(n);
  }
  return nodes;
}

std::vector<double> LumpedLengths(const BeamSpec& beam) {
  std::vector<double> lengths(beam.elements * beam.order + 1, 0.0);
  const double element_length = beam.length / beam.elements;
  for (int e = 0; e < beam.elements; ++e) {
    for (int k = 0; k <= beam.order; ++k) {
      lengths[e * beam.order + k] += 0.5 * element_length * ShapeIntegral(beam.order, k);
    }
  }
  return lengths;
}

Eigen::Matrix<double, 6, 6> BeamSectionStiffness(const BeamSectionSpec& section) {
  Eigen::Matrix<double, 6, 6> T = Eigen::Matrix<double, 6, 6>::Identity();
  T(1, 3) = -section.shear_center_offset.y();
  T(2, 3) = section.shear_center_offset.x();
  return T.transpose() * section.stiffness * T;
}

ElementPoint LocateOnBeam(const BeamSpec& beam, double s) {
  const double element_length = beam.length / beam.elements;
  ElementPoint p;
  p.element = std::min(beam.elements - 1, std::max(0, static_cast<int>(std::floor(s / element_length))));
  p.s = std::min(element_length, std::max(0.0, s - p.element * element_length));
  return p;
}

std::vector<LoadSpec> NodalLoads(const LoadSpec& distributed, const std::vector<double>& lumped_lengths) {
  std::vector<LoadSpec> nodal;
  for (double length : lumped_lengths) {
    LoadSpec load = distributed;
    load.distributed = false;
    load.p_BoP_B = Vec3::Zero();
    load.vector *= length;
    nodal.push_back(load);
  }
  return nodal;
}

int StationAt(const std::vector<double>& stations, double s, double length) {
  for (size_t k = 0; k < stations.size(); ++k) {
    if (std::abs(stations[k] - s) <= kStationTolerance * length) return static_cast<int>(k);
  }
  return -1;
}

std::string OffNodeText(const BeamSpec& beam, double x) {
  const std::vector<double> stations = BeamStations(beam);
  const int last = static_cast<int>(stations.size()) - 1;
  const double spacing = beam.length / last;
  const int nearest = static_cast<int>(std::min<double>(last, std::max(0.0, std::round(x / spacing))));
  const std::string where = x > beam.length ? "is past its end" : x < 0.0 ? "is before its root" : "is not at a node";
  std::string positions;
  if (stations.size() <= kListedNodes) {
    for (double s : stations) positions += (positions.empty() ? ": " : ", ") + FormatNumber(s);
  } else {
    positions = " k * " + FormatNumber(beam.length) + " / " + std::to_string(last) + " for k = 0.." +
                std::to_string(last);
  }
  return "x = " + FormatNumber(x) + " m on beam '" + beam.name + "' " + where + " (length " +
         FormatNumber(beam.length) + " m, " + std::to_string(beam.elements) + " element(s) of order " +
         std::to_string(beam.order) + ": nodes 0.." + std::to_string(last) + " every " + FormatNumber(spacing) +
         " m, the nearest node " + std::to_string(nearest) + " at " + FormatNumber(stations[nearest]) +
         " m); expected a node position [m]" + positions;
}

void ValidateBeam(const std::string& prefix, const BeamSpec& beam) {
  auto fail = [&](const std::string& field, const std::string& what) {
    throw ConfigError(prefix + "beams." + beam.name + "." + field + ": " + what);
  };
  if (!(beam.length > 0.0)) fail("length", std::to_string(beam.length) + " is not positive; expected a length > 0 [m]");
  if (beam.elements < 1) fail("elements", std::to_string(beam.elements) + " is below 1; expected a whole number >= 1");
  if (beam.order < 1 || beam.order > 3) fail("order", std::to_string(beam.order) + " is not 1, 2 or 3");
  if (!std::isnormal(beam.length / beam.elements)) {
    // the elements divide by their length (their Jacobian); 4.9e-324 m in 2 elements underflows to 0
    std::ostringstream msg;
    msg << beam.length << " m in " << beam.elements << " elements gives elements of no length; expected a length "
        << "> " << beam.elements * std::numeric_limits<double>::min() << " [m] or fewer elements";
    fail("length", msg.str());
  }
  const auto& C = beam.section.stiffness;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eig(0.5 * (C + C.transpose()));
  if (!(eig.eigenvalues().minCoeff() > 0.0)) {
    std::ostringstream msg;
    msg << "section stiffness is not positive definite (smallest eigenvalue " << eig.eigenvalues().minCoeff()
        << "); expected EA, GA2, GA3, GJ, EI2, EI3 > 0 and couplings that keep the 6x6 matrix positive definite";
    fail("section", msg.str());
  }
  if (!(beam.damping >= 0.0)) {
    fail("damping", std::to_string(beam.damping) + " is negative; expected a damping time mu >= 0 [s]");
  }
  if (!(beam.section.mass_per_length > 0.0)) {
    fail("section.m", "mass per length is not positive; expected m > 0 [kg/m]");
  }
  if ((beam.section.inertia_per_length.array() < 0.0).any()) {
    fail("section.m_ii", "a mass moment per length is negative; expected values >= 0 [kg m]");
  }
}

}  // namespace flexmbd
