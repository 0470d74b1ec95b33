// The Newmark family as one parameterised scheme (beta, gamma, alpha_f, alpha_m) with named
// presets. The discrete equilibrium (Chung & Hulbert's generalized-alpha form):
//   (1-am) M a_{n+1} + am M a_n + (1-af) F(u_{n+1}, v_{n+1}, t_{n+1}) + af F(u_n, v_n, t_n)
//       + f_c(u_{n+1}) = 0,        F(u, v, t) = C v + K u - f_ext(t)
//   u_{n+1} = u_n + dt v_n + dt^2 ((1/2 - beta) a_n + beta a_{n+1})
//   v_{n+1} = v_n + dt ((1 - gamma) a_n + gamma a_{n+1})
// Constraint (contact) forces f_c act at t_{n+1}, unweighted.
// Presets:
//   "average acceleration"            beta = 1/4, gamma = 1/2 (trapezoidal rule)
//   "modified average acceleration"   alpha in [-1/3, 0]: beta = (1-alpha)^2/4,
//                                     gamma = 1/2 - alpha, af = am = 0 (equilibrium at t_{n+1};
//                                     Code_Aster's HHT with MODI_EQUI = NON)
//   "HHT"                             alpha in [-1/3, 0]: the same beta, gamma, af = -alpha,
//                                     am = 0 (internal and external forces weighted 1+alpha
//                                     at t_{n+1}, -alpha at t_n; MODI_EQUI = OUI)
//   "generalized-alpha"               rho_inf in [0, 1]: am = (2 rho - 1)/(rho + 1),
//                                     af = rho/(rho + 1), gamma = 1/2 - am + af,
//                                     beta = (1 - am + af)^2 / 4
//   "Newmark"                         beta, gamma given, unconditionally stable: 2 beta >= gamma >= 1/2
// Parameters out of the stable range throw SchemeRangeError (the caller reports it as an
// input error naming its parameter).
#pragma once
#include <stdexcept>
#include <string>
#include <vector>

#include "timeint/SecondOrderOperator.hpp"

namespace choc {

class SchemeRangeError : public std::invalid_argument {
 public:
  SchemeRangeError(std::string parameter, const std::string& what)
      : std::invalid_argument(what), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }  // "Alpha", "Spectral Radius", ...

 private:
  std::string parameter_;
};

class NewmarkFamily {
 public:
  static const std::vector<std::string>& presetNames();
  static NewmarkFamily averageAcceleration();
  static NewmarkFamily modifiedAverageAcceleration(double alpha);
  static NewmarkFamily hht(double alpha);
  static NewmarkFamily generalizedAlpha(double rhoInfinity);
  static NewmarkFamily newmark(double beta, double gamma);
  // By preset name; `alpha`, `rho`, `beta`, `gamma` are used by the presets that need them.
  static NewmarkFamily fromPreset(const std::string& name, double alpha, double rho, double beta,
                                  double gamma);

  const std::string& name() const { return name_; }
  double beta() const { return beta_; }
  double gamma() const { return gamma_; }
  double alphaF() const { return alphaF_; }  // weight of t_n in the forces
  double alphaM() const { return alphaM_; }  // weight of t_n in the inertia

  // 2 when gamma = 1/2 - am + af (second-order accurate), else 1.
  int order() const;
  // Unconditional stability of the linear undamped problem (all presets are, by validation).
  bool unconditionallyStable() const;
  // Spectral radius of the amplification matrix as omega dt -> infinity (closed forms).
  double spectralRadiusAtInfinity() const;
  // One line: name, coefficients, order, stability, rho_inf.
  std::string describe() const;

  // Newton matrix of the step equation with u_{n+1} as unknown: W = ca M + cv C + cd K.
  EffectiveCoefficients effectiveCoefficients(double dt) const;

 private:
  NewmarkFamily(std::string name, double beta, double gamma, double af, double am)
      : name_(std::move(name)), beta_(beta), gamma_(gamma), alphaF_(af), alphaM_(am) {}
  std::string name_;
  double beta_, gamma_, alphaF_, alphaM_;
};

}  // namespace choc
