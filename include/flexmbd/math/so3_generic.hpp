#pragma once
/// @file
/// The rotation formulas of so3.hpp written once for any scalar type: double, or Eigen's AutoDiffScalar where
/// a test differentiates through rotations to check an analytic derivative. so3.cpp instantiates them for double.

#include <cmath>

#include <Eigen/Core>

namespace flexmbd {
namespace so3 {

template <class T>
using Vector3 = Eigen::Matrix<T, 3, 1>;
template <class T>
using Matrix3 = Eigen::Matrix<T, 3, 3>;

/// The value of a scalar, for branching on it (an AutoDiffScalar's value; a double itself).
inline double ValueOf(double x) { return x; }
template <class T>
double ValueOf(const T& x) {
  return x.value();
}

/// Below this squared angle the trigonometric ratios use their series: at 0.25 (0.5 rad) the first omitted
/// terms are below 1e-16 relative, and the closed forms above it lose at most 6 eps / 0.25 to cancellation.
constexpr double kSeriesLimitSquared = 0.25;

/// sum_k (-1)^k x2^k / (2k + first)!, seven terms.
template <class T>
T AlternatingSeries(const T& x2, int first) {
  double factorial = 1.0;
  for (int j = 2; j <= first; ++j) factorial *= j;
  T term = T(1.0 / factorial), sum = T(0.0);
  for (int k = 0; k < 7; ++k) {
    sum += term;
    term *= -x2 / double((2 * k + first + 1) * (2 * k + first + 2));
  }
  return sum;
}

template <class T>
Matrix3<T> SkewOf(const Vector3<T>& a) {
  Matrix3<T> S;
  S << T(0.0), -a.z(), a.y(), a.z(), T(0.0), -a.x(), -a.y(), a.x(), T(0.0);
  return S;
}

/// sin(x)/x and (1 - cos x)/x^2 of x2 = x^2; the latter as sinc(x/2)^2 / 2 (no cancellation).
template <class T>
void SinRatios(const T& x2, T* sin_ratio, T* cos_ratio) {
  using std::sin;
  using std::sqrt;
  if (ValueOf(x2) < kSeriesLimitSquared) {
    *sin_ratio = AlternatingSeries(x2, 1);
    *cos_ratio = AlternatingSeries(x2, 2);
    return;
  }
  const T x = sqrt(x2);
  *sin_ratio = sin(x) / x;
  const T half = sin(0.5 * x) / (0.5 * x);
  *cos_ratio = 0.5 * half * half;
}

/// (x - sin x)/x^3 of x2 = x^2.
template <class T>
T CubicRatio(const T& x2) {
  using std::sin;
  using std::sqrt;
  if (ValueOf(x2) < kSeriesLimitSquared) return AlternatingSeries(x2, 3);
  const T x = sqrt(x2);
  return (x - sin(x)) / (x2 * x);
}

/// The three maps of a rotation vector from its skew matrix K and ratios a = sin(x)/x, b = (1 - cos x)/x^2,
/// c = (x - sin x)/x^3, so that callers needing several share one evaluation of the ratios. K^2 stays inside
/// each sum: formed once apart, it is summed in another order, and that round-off alone sent the chaotic double
/// pendulum of EnergyPreservingScheme from under 100 to 1,253 rejected steps.
/// Rodrigues: I + a K + b K^2.
template <class T>
Matrix3<T> ExpFromRatios(const Matrix3<T>& K, const T& a, const T& b) {
  return Matrix3<T>::Identity() + a * K + b * (K * K);
}

/// Right Jacobian: I - b K + c K^2.
template <class T>
Matrix3<T> RightJacobianFromRatios(const Matrix3<T>& K, const T& b, const T& c) {
  return Matrix3<T>::Identity() - b * K + c * (K * K);
}

/// Secant operator: a I + b K.
template <class T>
Matrix3<T> SecantFromRatios(const Matrix3<T>& K, const T& a, const T& b) {
  return a * Matrix3<T>::Identity() + b * K;
}

template <class T>
Matrix3<T> ExpOf(const Vector3<T>& v) {
  T a, b;
  SinRatios(T(v.squaredNorm()), &a, &b);
  return ExpFromRatios<T>(SkewOf<T>(v), a, b);
}

template <class T>
Matrix3<T> RightJacobianOf(const Vector3<T>& v) {
  const T x2 = v.squaredNorm();
  T a, b;
  SinRatios(x2, &a, &b);
  return RightJacobianFromRatios<T>(SkewOf<T>(v), b, CubicRatio(x2));
}

}  // namespace so3
}  // namespace flexmbd
