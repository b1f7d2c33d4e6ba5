// Generalised unsteady thin-airfoil loads of a plunging, pitching section with a trailing-edge flap
// (docs/theory.md, (A2)-(A5)).

#include "flexmbd/aero/thin_airfoil_loads.hpp"

#include <algorithm>
#include <cmath>

namespace flexmbd {
namespace {
// Harmonics kept in the series of the flap shape (coefficients ~1/n^2, its slope ~1/n): the products summed
// converge as 1/n^3 or faster, so the loads are good to ~1/kHarmonics^2 = 6e-8 relative
// (PetersSection.FlapMatricesConvergeWithTheSeries).
constexpr int kHarmonics = 4096;

// int_0^pi sin(p phi) sin(r phi) dphi for p >= 1 and any integer r.
double SinSin(int p, int r) { return M_PI / 2 * ((p == r ? 1.0 : 0.0) - (p == -r ? 1.0 : 0.0)); }

// The acyclic potential jump of the downwash cos(n phi) (x = b cos phi): Psi_n = sum_p psi_p sin(p phi), with
// Psi_0 = 2 b sin(phi), Psi_1 = (b/2) sin(2 phi), Psi_n = b [sin((n+1) phi)/(n+1) - sin((n-1) phi)/(n-1)] (A2).
// int_{-b}^{b} Psi_n cos(m phi) dx, using sin(phi) cos(m phi) = [sin((m+1) phi) - sin((m-1) phi)] / 2.
double PsiMoment(double b, int n, int m) {
  auto term = [&](int p, double psi) { return psi * 0.5 * (SinSin(p, m + 1) - SinSin(p, m - 1)); };
  if (n == 0) return b * term(1, 2.0 * b);
  if (n == 1) return b * term(2, 0.5 * b);
  return b * (term(n + 1, b / (n + 1)) - term(n - 1, b / (n - 1)));
}
}  // namespace

void FlapShapeCoefficients(double semichord, double c, int num_terms, Eigen::VectorXd* f, Eigen::VectorXd* g) {
  const double b = semichord, th = std::acos(c);
  f->setZero(num_terms);
  g->setZero(num_terms);
  for (int n = 0; n < num_terms; ++n) {
    if (n == 0) {
      (*f)[0] = b / M_PI * (std::sin(th) - th * c);
      (*g)[0] = th / M_PI;
    } else if (n == 1) {
      (*f)[1] = b / M_PI * (th - 0.5 * std::sin(2.0 * th));
      (*g)[1] = 2.0 * std::sin(th) / M_PI;
    } else {
      (*f)[n] = b / M_PI *
                (std::sin((n - 1) * th) / (n - 1) + std::sin((n + 1) * th) / (n + 1) - 2.0 * c * std::sin(n * th) / n);
      (*g)[n] = 2.0 * std::sin(n * th) / (n * M_PI);
    }
  }
}

ThinAirfoilLoads::ThinAirfoilLoads(double b, double a, double c) : semichord(b) {
  const int K = kHarmonics;
  // Shapes s_k (downward displacement per unit q_k) and their slopes ds_k/dx as cosine series (A3).
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(3, K), G = Eigen::MatrixXd::Zero(3, K);
  S(0, 0) = 1.0;
  S(1, 0) = -a * b;
  S(1, 1) = b;
  G(1, 0) = 1.0;
  Eigen::VectorXd f, g;
  FlapShapeCoefficients(b, c, K, &f, &g);
  S.row(2) = f.transpose();
  G.row(2) = g.transpose();
  // P_kn = int Psi_n s_k dx, R_kn = int Psi_n s_k' dx; PsiMoment(n, m) vanishes unless |n - m| <= 2.
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(3, K), R = Eigen::MatrixXd::Zero(3, K);
  for (int n = 0; n < K; ++n) {
    for (int m = std::max(0, n - 2); m <= std::min(K - 1, n + 2); ++m) {
      const double moment = PsiMoment(b, n, m);
      if (moment == 0.0) continue;
      P.col(n) += moment * S.col(m);
      R.col(n) += moment * G.col(m);
    }
  }
  // The pressure rho (d/dt + U d/dx) DeltaPhi of the acyclic flow of w = sum_n w_n cos(n phi),
  // w_n = S_.n . q' + U G_.n . q, projected on s_k: rho [P w']_k - rho U [R w]_k (A4).
  Ma = P * S.transpose();
  Cnc = P * G.transpose() - R * S.transpose();
  Knc = -R * G.transpose();
  es = S.col(0);
  ef = S.col(0) - 0.5 * S.col(1);
  ew = S.col(0) + 0.5 * S.col(1);
  eg = G.col(0) + 0.5 * G.col(1);
}

Vec3 ThinAirfoilLoads::Forces(double rho, double U, const Vec3& q, const Vec3& qdot, const Vec3& qddot,
                              double lambda0) const {
  const double circulation = 2.0 * M_PI * rho * U * semichord;
  return -rho * (Ma * qddot + U * Cnc * qdot + U * U * Knc * q) -
         circulation * (es * (ew.dot(qdot) + U * eg.dot(q)) - ef * lambda0);
}

}  // namespace flexmbd
