#pragma once
/// @file
/// Where a beam's nodes are and how its mass is lumped on them (docs/theory.md, "Beams", (B6)).

#include <string>
#include <vector>

#include "flexmbd/model/model_spec.hpp"
#include "flexmbd/model/state.hpp"

namespace flexmbd {

/// Node positions along the beam from its root [m]: elements * order + 1 equally spaced stations.
std::vector<double> BeamStations(const BeamSpec& beam);

/// Initial node states: on the straight axis of the link frame, frames parallel to it, rigid initial motion.
std::vector<NodeState> BeamNodeStates(const BeamSpec& beam);

/// Share of the beam length lumped on each node: the integral of its shape function (row sums of the
/// consistent mass matrix), summed over the elements it belongs to [m]. The shares add up to the length.
std::vector<double> LumpedLengths(const BeamSpec& beam);

/// The 6x6 section stiffness about the beam axis (docs/theory.md, (B8)): C with its shear rows taken at the
/// shear centre, C_axis = T^T C T, T the identity but for the shear strains at the shear centre
/// gamma_2 - z_s kappa_1 and gamma_3 + y_s kappa_1.
Eigen::Matrix<double, 6, 6> BeamSectionStiffness(const BeamSectionSpec& section);

/// Where a beam station lies: the element index and the distance from that element's first node [m].
struct ElementPoint {
  int element = 0;
  double s = 0.0;
};
ElementPoint LocateOnBeam(const BeamSpec& beam, double s);

/// The consistent nodal loads of a load uniformly distributed along a beam (theory (B9)): node k takes the
/// vector times its lumped length (the integral of its shape function); dead stays dead, follower follows the
/// node's section frame.
std::vector<LoadSpec> NodalLoads(const LoadSpec& distributed, const std::vector<double>& lumped_lengths);

/// Index of the station at distance s from the root, or -1 if none is within tolerance of it.
int StationAt(const std::vector<double>& stations, double s, double length);

/// Why `x` [m] along `beam` is no node of it, for a message: "x = 1.5 m on beam 'arm' is past its end (...)", with
/// the beam's length, its node layout and the nearest node, and the positions expected.
std::string OffNodeText(const BeamSpec& beam, double x);

/// Checks a beam's data; throws ConfigError naming the beam, the field and the expected form.
void ValidateBeam(const std::string& source_prefix, const BeamSpec& beam);

}  // namespace flexmbd
