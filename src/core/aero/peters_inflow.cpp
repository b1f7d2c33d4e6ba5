// Peters' induced-flow matrices (docs/theory.md, (A1); REFERENCES section 5.2).

#include "flexmbd/aero/peters_inflow.hpp"

#include <cmath>

namespace flexmbd {

PetersInflow::PetersInflow(int num_states) {
  const int N = num_states;
  A = Eigen::MatrixXd::Zero(N, N);
  b = Eigen::VectorXd::Zero(N);
  c = Eigen::VectorXd::Zero(N);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(N);
  if (N == 0) return;
  d[0] = 0.5;
  for (int n = 1; n <= N; ++n) {
    const double sign = n % 2 == 1 ? 1.0 : -1.0;  // (-1)^(n-1)
    // (N+n-1)! / ((N-n-1)! (n!)^2) through lgamma: exact to round-off for the N <= 10 the model takes.
    b[n - 1] = n < N ? sign * std::exp(std::lgamma(N + n) - std::lgamma(N - n) - 2.0 * std::lgamma(n + 1.0)) : sign;
    c[n - 1] = 2.0 / n;
    if (n > 1) A(n - 1, n - 2) = 1.0 / (2.0 * n);
    if (n < N) A(n - 1, n) = -1.0 / (2.0 * n);
  }
  A += d * b.transpose() + c * d.transpose() + 0.5 * c * b.transpose();
}

}  // namespace flexmbd
