#pragma once
/// @file
/// Lagrange shape functions of a beam element (docs/theory.md, (B1)) tabulated at a few points of it: the
/// Gauss points of its reduced rule, or one station.

#include <array>

namespace flexmbd {

struct BeamShape {
  static constexpr int kMaxNodes = 4;   ///< cubic elements
  static constexpr int kMaxPoints = 3;  ///< Gauss points of the reduced rule of a cubic element
  int order = 1;                        ///< 1..3; the element has order + 1 equally spaced nodes
  int reference = 0;                    ///< the node rotations are interpolated relative to (the middle one)
  int num_points = 0;
  std::array<std::array<double, kMaxNodes>, kMaxPoints> N{};     ///< N[g][k]
  std::array<std::array<double, kMaxNodes>, kMaxPoints> dNds{};  ///< dN_k/ds at point g [1/m]
  std::array<double, kMaxPoints> weight_ds{};                     ///< Gauss weight times ds/dxi [m]
  std::array<double, kMaxPoints> xi{};                            ///< the points on [-1, 1]

  int num_nodes() const { return order + 1; }
};

/// The shape functions at the `order` Gauss points of the reduced rule (free of shear locking), with weights.
BeamShape GaussShape(int order, double length);

/// The shape functions at one point xi in [-1, 1] (weight zero).
BeamShape PointShape(int order, double length, double xi);

}  // namespace flexmbd
