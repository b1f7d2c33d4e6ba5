#pragma once
/// @file
/// The force law of an elastic stop at approach a >= 0 (docs/theory.md, "Stops", (C2)-(C4)):
///   V(a) = k a^(n+1) / (n + 1),   F = V'(a) [1 + chi a_dot],   chi = alpha_e / v_in,
/// n = 1 for the linear law, alpha_e from the coefficient of restitution by the exact relation of the
/// Hunt-Crossley equation (HuntCrossleyDampingNumber), v_in the approach speed when the contact began.

#include "flexmbd/model/model_spec.hpp"

namespace flexmbd {

/// The dimensionless damping alpha_e = chi v_in for which the Hunt-Crossley contact m a'' = -k a^n (1 + chi a')
/// rebounds with restitution e, for any n and k: the root of ln(1 + alpha) - ln(1 - alpha e) = alpha (1 + e)
/// (docs/theory.md, (C4); Carvalho & Martins 2019). @pre e in (0, 1]; e = 1 gives 0.
double HuntCrossleyDampingNumber(double restitution);

class ContactLaw {
 public:
  explicit ContactLaw(const StopSpec& stop);

  /// The approach a may be negative (open gap): V and V' vanish there.
  double Potential(double a) const;  ///< V(a) [J]
  double Force(double a) const;      ///< V'(a) [N]
  /// V''(a) [N/m]: 0 for an open gap, and touching (a = 0) the linear law's k, Hertz's 0.
  double Stiffness(double a) const;
  /// The approach [m] at which the force is `force` [N] > 0: the inverse of V'.
  double ApproachAt(double force) const;
  bool linear() const { return exponent_ == 1.0; }  ///< F = k a
  /// The exact discrete gradient (V(a_f) - V(a_i)) / (a_f - a_i) (V' at the midpoint when they coincide) [N],
  /// and its derivative with respect to a_f in *d_da_f [N/m]. A step that opens or closes the gap takes
  /// a_i or a_f negative, so the quotient is over the whole motion of the step.
  double DiscreteForce(double a_i, double a_f, double* d_da_f) const;
  double damping_number() const { return damping_number_; }  ///< alpha_e

 private:
  double stiffness_, exponent_, damping_number_;
};

}  // namespace flexmbd
