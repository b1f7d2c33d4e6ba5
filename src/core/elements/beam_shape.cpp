#include "flexmbd/elements/beam_shape.hpp"

#include <cmath>

namespace flexmbd {
namespace {

// Values and xi-derivatives of the Lagrange polynomials on order + 1 equally spaced nodes of [-1, 1].
void Lagrange(int order, double xi, std::array<double, BeamShape::kMaxNodes>* N,
              std::array<double, BeamShape::kMaxNodes>* dN) {
  const int n = order + 1;
  auto node = [order](int k) { return -1.0 + 2.0 * k / order; };
  for (int k = 0; k < n; ++k) {
    (*N)[k] = 1.0;
    (*dN)[k] = 0.0;
    for (int j = 0; j < n; ++j) {
      if (j == k) continue;
      (*N)[k] *= (xi - node(j)) / (node(k) - node(j));
      double term = 1.0 / (node(k) - node(j));
      for (int m = 0; m < n; ++m) {
        if (m != k && m != j) term *= (xi - node(m)) / (node(k) - node(m));
      }
      (*dN)[k] += term;
    }
  }
}

void Tabulate(int g, double xi, double length, BeamShape* shape) {
  shape->xi[g] = xi;
  Lagrange(shape->order, xi, &shape->N[g], &shape->dNds[g]);
  for (double& d : shape->dNds[g]) d *= 2.0 / length;
}

BeamShape Empty(int order) {
  BeamShape shape;
  shape.order = order;
  shape.reference = order / 2;
  return shape;
}

}  // namespace

BeamShape GaussShape(int order, double length) {
  BeamShape shape = Empty(order);
  static const double kRoot3 = 1.0 / std::sqrt(3.0), kRoot06 = std::sqrt(0.6);
  struct Rule {
    int count;
    double points[3], weights[3];
  };
  const Rule rule = order == 1   ? Rule{1, {0.0}, {2.0}}
                    : order == 2 ? Rule{2, {-kRoot3, kRoot3}, {1.0, 1.0}}
                                 : Rule{3, {-kRoot06, 0.0, kRoot06}, {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0}};
  shape.num_points = rule.count;
  for (int g = 0; g < rule.count; ++g) {
    Tabulate(g, rule.points[g], length, &shape);
    shape.weight_ds[g] = rule.weights[g] * 0.5 * length;
  }
  return shape;
}

BeamShape PointShape(int order, double length, double xi) {
  BeamShape shape = Empty(order);
  shape.num_points = 1;
  Tabulate(0, xi, length, &shape);
  return shape;
}

}  // namespace flexmbd
