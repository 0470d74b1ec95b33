#include "reference/BarImpactExact.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/Errors.hpp"

namespace choc {
namespace {

const char* const kFile = "exact solution";

std::string show(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

void requireFinite(const char* name, double v) {
  if (!std::isfinite(v)) throwInput(kFile, name, show(v), "must be a finite number");
}

void requirePositive(const char* name, double v) {
  requireFinite(name, v);
  if (!(v > 0.0)) throwInput(kFile, name, show(v), "must be > 0");
}

}  // namespace

BarImpactExact::BarImpactExact(const BarImpactParameters& p) : p_(p) {
  requirePositive("length", p.length);
  requirePositive("waveSpeed", p.waveSpeed);
  requirePositive("impedance", p.impedance);
  requireFinite("impactVelocity", p.impactVelocity);
  if (p.impactVelocity == 0.0)
    throwInput(kFile, "impactVelocity", "0", "must be non-zero", "the bars never meet at rest");
  requireFinite("contactStart", p.contactStart);
  if (p.contactStart < 0.0)
    throwInput(kFile, "contactStart", show(p.contactStart), "must be >= 0");
  if (p.rigidWall && p.bilateral)
    throwInput(kFile, "bilateral", "true", "a rigid wall is unilateral");
  if (p.freeEnd && !p.rigidWall)
    throwInput(kFile, "freeEnd", "true", "the free end is available against a rigid wall only");
  tau_ = 2.0 * p.length / p.waveSpeed;
  if (!(tau_ > 0.0) || !std::isfinite(tau_))
    throwInput(kFile, "waveSpeed", show(p.waveSpeed), "gives a transit time 2L/c that is not a "
               "positive finite number");
}

double BarImpactExact::barWaveSpeed(double youngsModulus, double density) {
  requirePositive("youngsModulus", youngsModulus);
  requirePositive("density", density);
  return std::sqrt(youngsModulus / density);
}

double BarImpactExact::oedometricWaveSpeed(double youngsModulus, double poissonsRatio,
                                           double density) {
  requirePositive("youngsModulus", youngsModulus);
  requirePositive("density", density);
  requireFinite("poissonsRatio", poissonsRatio);
  if (!(poissonsRatio > -1.0 && poissonsRatio < 0.5))
    throwInput(kFile, "poissonsRatio", show(poissonsRatio), "must lie in (-1, 0.5)");
  const double nu = poissonsRatio;
  return std::sqrt(youngsModulus * (1.0 - nu) / (density * (1.0 + nu) * (1.0 - 2.0 * nu)));
}

double BarImpactExact::phase(double t) const {
  if (!std::isfinite(t) || t < 0.0)
    throw std::invalid_argument("exact solution: time " + show(t) +
                                " is not a finite time >= 0");
  return (t - p_.contactStart) / tau_;
}

// u_A = v0 t0 + (v0 tau / 2) g(s) after first contact, with g the shape in wave transits.
double BarImpactExact::displacementA(double t) const {
  const double s = phase(t);
  const double v0 = p_.impactVelocity;
  if (p_.rigidWall) {  // s in units of 2L/c: the free end turns at s = 1/2, the contact end at 1
    const double turn = p_.freeEnd ? 0.5 : 1.0, t0 = p_.contactStart;
    if (s < (p_.freeEnd ? 0.5 : 0.0)) return v0 * t;
    const double held = v0 * (t0 + (p_.freeEnd ? 0.5 * tau_ : 0.0));
    return s < turn ? held : held - v0 * (t - t0 - turn * tau_);
  }
  if (t < p_.contactStart) return v0 * t;
  double g;
  if (p_.bilateral) {
    const double r = s - 4.0 * std::floor(s / 4.0);  // in [0, 4)
    g = r < 1.0 ? r : (r < 3.0 ? 2.0 - r : r - 4.0);
  } else {
    g = s < 1.0 ? s : (s < 2.0 ? 2.0 - s : -2.0 * (s - 2.0));
  }
  return v0 * p_.contactStart + 0.5 * v0 * tau_ * g;
}

double BarImpactExact::velocityA(double t) const {
  const double s = phase(t);
  const double v0 = p_.impactVelocity;
  if (p_.rigidWall) {
    if (p_.freeEnd) return s < 0.5 ? v0 : -v0;
    return s < 0.0 ? v0 : (s < 1.0 ? 0.0 : -v0);
  }
  if (t < p_.contactStart) return v0;
  if (p_.bilateral) {
    const double r = s - 4.0 * std::floor(s / 4.0);
    return (r < 1.0 || r >= 3.0) ? 0.5 * v0 : -0.5 * v0;
  }
  return s < 1.0 ? 0.5 * v0 : (s < 2.0 ? -0.5 * v0 : -v0);
}

double BarImpactExact::contactForce(double t) const {
  const double s = phase(t);
  if (t < p_.contactStart) return 0.0;
  const double f = contactForceMagnitude();
  if (p_.rigidWall) return s < 1.0 ? f : 0.0;
  if (p_.bilateral) {
    const double halfPeriods = std::floor(s / 2.0);
    return std::fmod(halfPeriods, 2.0) == 0.0 ? f : -f;
  }
  return s < 2.0 ? f : 0.0;
}

double BarImpactExact::peakDisplacement() const {
  if (p_.rigidWall) return absV0() * (p_.contactStart + (p_.freeEnd ? 0.5 * tau_ : 0.0));
  return absV0() * (p_.contactStart + 0.5 * tau_);
}

double BarImpactExact::contactEnd() const {
  return p_.contactStart + contactDuration();
}

double BarImpactExact::contactDuration() const {
  if (p_.rigidWall) return tau_;
  return p_.bilateral ? std::numeric_limits<double>::infinity() : 2.0 * tau_;
}

}  // namespace choc
