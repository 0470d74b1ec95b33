#include "timeint/NewmarkFamily.hpp"

#include <cmath>
#include <cstdio>

namespace choc {

namespace {

void requireAlpha(double alpha) {
  if (!(alpha >= -1.0 / 3.0 && alpha <= 0.0))
    throw SchemeRangeError("Alpha", "alpha must lie in [-1/3, 0] (unconditional stability and "
                                    "numerical damping of high frequencies)");
}

}  // namespace

const std::vector<std::string>& NewmarkFamily::presetNames() {
  static const std::vector<std::string> names = {"average acceleration",
                                                 "modified average acceleration", "HHT",
                                                 "generalized-alpha", "Newmark"};
  return names;
}

NewmarkFamily NewmarkFamily::averageAcceleration() {
  return NewmarkFamily("average acceleration", 0.25, 0.5, 0.0, 0.0);
}

NewmarkFamily NewmarkFamily::modifiedAverageAcceleration(double alpha) {
  requireAlpha(alpha);
  return NewmarkFamily("modified average acceleration", 0.25 * (1 - alpha) * (1 - alpha),
                       0.5 - alpha, 0.0, 0.0);
}

NewmarkFamily NewmarkFamily::hht(double alpha) {
  requireAlpha(alpha);
  return NewmarkFamily("HHT", 0.25 * (1 - alpha) * (1 - alpha), 0.5 - alpha, -alpha, 0.0);
}

NewmarkFamily NewmarkFamily::generalizedAlpha(double rho) {
  if (!(rho >= 0.0 && rho <= 1.0))
    throw SchemeRangeError("Spectral Radius", "rho_inf must lie in [0, 1]");
  const double am = (2 * rho - 1) / (rho + 1), af = rho / (rho + 1);
  const double g = 0.5 - am + af;
  return NewmarkFamily("generalized-alpha", 0.25 * (1 - am + af) * (1 - am + af), g, af, am);
}

NewmarkFamily NewmarkFamily::newmark(double beta, double gamma) {
  if (!(gamma >= 0.5))
    throw SchemeRangeError("Gamma", "gamma must be >= 1/2 (unconditional stability)");
  if (!(2 * beta >= gamma) || !(beta <= 1.0))
    throw SchemeRangeError("Beta", "beta must satisfy gamma/2 <= beta <= 1 (unconditional "
                                   "stability of the implicit scheme)");
  return NewmarkFamily("Newmark", beta, gamma, 0.0, 0.0);
}

NewmarkFamily NewmarkFamily::fromPreset(const std::string& name, double alpha, double rho,
                                        double beta, double gamma) {
  if (name == "average acceleration") return averageAcceleration();
  if (name == "modified average acceleration") return modifiedAverageAcceleration(alpha);
  if (name == "HHT") return hht(alpha);
  if (name == "generalized-alpha") return generalizedAlpha(rho);
  if (name == "Newmark") return newmark(beta, gamma);
  throw SchemeRangeError("Scheme", "unknown scheme '" + name + "'");
}

int NewmarkFamily::order() const {
  return std::abs(gamma_ - (0.5 - alphaM_ + alphaF_)) < 1e-12 ? 2 : 1;
}

bool NewmarkFamily::unconditionallyStable() const {
  // Chung & Hulbert: am <= af <= 1/2, gamma >= 1/2 - am + af, beta >= gamma / 2 ... with the
  // Newmark condition 2 beta >= gamma >= 1/2 as the special case am = af = 0.
  const double tol = 1e-14;
  return alphaM_ <= alphaF_ + tol && alphaF_ <= 0.5 + tol &&
         gamma_ >= 0.5 - alphaM_ + alphaF_ - tol && beta_ >= 0.25 + 0.5 * (alphaF_ - alphaM_) - tol;
}

double NewmarkFamily::spectralRadiusAtInfinity() const {
  if (alphaM_ != 0.0 || alphaF_ != 0.0) {
    if (alphaM_ == 0.0) return (1 - alphaF_) / (1 + alphaF_);  // HHT: (1+alpha)/(1-alpha)
    return alphaF_ / (1 - alphaF_);                           // generalized-alpha: rho_inf
  }
  // Newmark: for omega dt -> infinity the amplification acts on (dt v, dt^2 a) with
  // trace 2 - (gamma + 1/2)/beta and determinant (1/2 + beta - gamma)/beta.
  const double tr = 2 - (gamma_ + 0.5) / beta_, det = (0.5 + beta_ - gamma_) / beta_;
  const double disc = tr * tr - 4 * det;
  if (disc <= 0) return std::sqrt(std::max(det, 0.0));
  const double r1 = 0.5 * (tr + std::sqrt(disc)), r2 = 0.5 * (tr - std::sqrt(disc));
  return std::max(std::abs(r1), std::abs(r2));
}

std::string NewmarkFamily::describe() const {
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "%s: beta = %.6g, gamma = %.6g, alpha_f = %.6g, alpha_m = %.6g; order %d, %s, "
                "rho_inf = %.4g",
                name_.c_str(), beta_, gamma_, alphaF_, alphaM_, order(),
                unconditionallyStable() ? "unconditionally stable" : "conditionally stable",
                spectralRadiusAtInfinity());
  return buf;
}

EffectiveCoefficients NewmarkFamily::effectiveCoefficients(double dt) const {
  EffectiveCoefficients c;
  c.ca = (1 - alphaM_) / (beta_ * dt * dt);
  c.cv = (1 - alphaF_) * gamma_ / (beta_ * dt);
  c.cd = 1 - alphaF_;
  return c;
}

}  // namespace choc
