#pragma once
// Closed forms the verification tests compare with.

#include <cmath>

namespace flexmbd {
namespace test {

// Complete elliptic integral of the first kind K(k) by the arithmetic-geometric mean (exact to round-off):
// K(k) = pi / (2 AGM(1, sqrt(1 - k^2))).
inline double EllipticK(double k) {
  double a = 1.0, b = std::sqrt(1.0 - k * k);
  for (int i = 0; i < 40; ++i) {
    const double next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = next;
  }
  return M_PI / (2.0 * a);
}

}  // namespace test
}  // namespace flexmbd
