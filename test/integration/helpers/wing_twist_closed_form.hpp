#pragma once
// The static aeroelastic twist of the uniform cantilever wing of test/data/yaml/wing_twist_strips.yaml (its
// header gives the equations) and the steady thin-airfoil loads per unit span of its strips: the reference of
// StripStations.* (test/io) and StripLoads.* (the strips-only ~aero_loads rostest).

#include <cmath>

namespace flexmbd {
namespace test {

struct WingTwistClosedForm {
  // The case's data (the YAML files).
  static constexpr double kLength = 6.096, kGJ = 1.0e4, kRho = 1.225, kSemichord = 0.5, kA = -0.2;
  static constexpr double kStreamAlong = 20.0, kStreamUp = 0.04;
  static constexpr double kStations[] = {0.0, 1.0, 2.5, 4.064, 6.096};  ///< output.strip_stations.wing

  double speed_squared = kStreamAlong * kStreamAlong + kStreamUp * kStreamUp;
  double alpha0 = std::atan2(kStreamUp, kStreamAlong);
  double arm = kSemichord * (0.5 + kA);  ///< the quarter chord ahead of the elastic axis
  double lambda = std::sqrt(2 * M_PI * kRho * speed_squared * kSemichord * arm / kGJ);

  /// Nose-up twist at distance y from the root.
  double Twist(double y) const {
    return alpha0 * (std::tan(lambda * kLength) * std::sin(lambda * y) + std::cos(lambda * y) - 1.0);
  }
  double TipTwist() const { return Twist(kLength); }
  /// L = 2 pi rho u b w34 with u = |V| cos(alpha), w34 = |V| sin(alpha) in steady flow (theory (A8), (A9)).
  double Lift(double y) const { return LiftAt(alpha0 + Twist(y)); }
  double RootLift() const { return LiftAt(alpha0); }
  /// Steady: the circulatory lift acts at the quarter chord, `arm` ahead of the elastic axis.
  double Moment(double y) const { return arm * Lift(y); }

 private:
  double LiftAt(double alpha) const { return M_PI * kRho * kSemichord * speed_squared * std::sin(2 * alpha); }
};

}  // namespace test
}  // namespace flexmbd
