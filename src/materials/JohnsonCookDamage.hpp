// Johnson and Cook's cumulative damage (Johnson and Cook 1985, Eng. Fract. Mech. 21), reported,
// not coupled: it does not soften the stress and no element is eroded. The failure strain
//     eps_f = (D1 + D2 exp(D3 sigma*)) (1 + D4 ln(max(rate / rate_0, 1))) (1 + D5 T*)
// with sigma* = sigma_m / sigma_vm the stress triaxiality (the mean stress over the von Mises
// stress, of the Cauchy stress at the end of the increment), rate = d alpha / dt over the
// increment and rate_0, T* = (T - T_0) / (T_m - T_0) clamped to [0, 1] the flow stress's
// (FlowStress.hpp; T the increment's start's, as there). The damage sums the plastic increments
// over the failure strain at each one,
//     D = sum d alpha / eps_f,
// and failure is predicted where D reaches 1. D grows only while the point yields.
//
// Range: D2 >= 0, D1 >= 0, D1 + D2 > 0, D4 >= 0 and D5 >= 0, so that eps_f > 0 at every
// triaxiality, rate and temperature. Johnson and Cook's own fits satisfy these except their
// negative D1 (Armco iron, Ti-6Al-4V), whose failure strain turns negative at high triaxiality
// (outside the fit's range): refused.
#pragma once
#include "materials/FlowStress.hpp"

namespace choc {

struct JohnsonCookDamageParameters {
  bool enabled = false;
  double D1 = 0.0, D2 = 0.0, D3 = 0.0, D4 = 0.0, D5 = 0.0;
};

class JohnsonCookDamage {
 public:
  JohnsonCookDamage() = default;
  // Throws std::invalid_argument naming the parameter and its value when out of the range above.
  JohnsonCookDamage(const JohnsonCookDamageParameters& d, const JohnsonCookParameters& flow);
  bool enabled() const { return d_.enabled; }
  // eps_f at the triaxiality, the plastic increment dalpha over dt (dt <= 0: no rate effect) and
  // the temperature.
  double failureStrain(double triaxiality, double dalpha, double dt, double temperature) const;

 private:
  JohnsonCookDamageParameters d_;
  JohnsonCookParameters flow_;
};

}  // namespace choc
