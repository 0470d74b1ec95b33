#include "timeint/ModalIntegrator.hpp"

#include <cmath>
#include <stdexcept>

namespace choc {

const std::vector<std::string>& modalSchemeNames() {
  static const std::vector<std::string> n = {"symplectic Euler", "central differences", "adaptive"};
  return n;
}

ModalScheme parseModalScheme(const std::string& name) {
  if (name == "symplectic Euler") return ModalScheme::SymplecticEuler;
  if (name == "central differences") return ModalScheme::CentralDifference;
  if (name == "adaptive") return ModalScheme::Adaptive;
  throw std::invalid_argument("unknown modal scheme '" + name + "'");
}

ModalIntegrator::ModalIntegrator(ModalScheme scheme, std::vector<double> omega2,
                                 std::vector<double> damping, ModalForce& force, int refinement)
    : scheme_(scheme), w2_(std::move(omega2)), c_(std::move(damping)), force_(force),
      refinement_(refinement) {}

void ModalIntegrator::initialize(ModalState& s, double t) const {
  const size_t n = w2_.size();
  s.t = t;
  s.f.assign(n, 0.0);
  s.a.assign(n, 0.0);
  force_.evaluate(t, s.q, s.v, 0.0, s.f);
  for (size_t k = 0; k < n; ++k) s.a[k] = s.f[k] - c_[k] * s.v[k] - w2_[k] * s.q[k];
}

double ModalIntegrator::dampingPower(const ModalState& s) const {
  double p = 0.0;
  for (size_t k = 0; k < c_.size(); ++k) p += c_[k] * s.v[k] * s.v[k];
  return p;
}

std::vector<double> ModalIntegrator::synchronizedVelocity(const ModalState& s) const {
  std::vector<double> v = s.v;
  if (scheme_ == ModalScheme::SymplecticEuler)
    for (size_t k = 0; k < v.size(); ++k) v[k] += 0.5 * lastStep_ * s.a[k];
  if (const std::vector<double>* fc = force_.constraintForce())
    for (size_t k = 0; k < v.size() && k < fc->size(); ++k) v[k] += 0.5 * lastStep_ * (*fc)[k];
  return v;
}

void ModalIntegrator::euler(ModalState& s, double h) const {
  const size_t n = w2_.size();
  lastStep_ = h;
  const double p0 = dampingPower(s);
  for (size_t k = 0; k < n; ++k) {
    s.v[k] += h * s.a[k];
    s.q[k] += h * s.v[k];
  }
  force_.project(h, s.q, s.v);
  s.t += h;
  force_.evaluate(s.t, s.q, s.v, h, s.f);
  for (size_t k = 0; k < n; ++k) s.a[k] = s.f[k] - c_[k] * s.v[k] - w2_[k] * s.q[k];
  dissipated_ += 0.5 * h * (p0 + dampingPower(s));
}

void ModalIntegrator::central(ModalState& s, double h) const {
  const size_t n = w2_.size();
  lastStep_ = h;
  const double p0 = dampingPower(s);
  for (size_t k = 0; k < n; ++k) {
    s.v[k] += 0.5 * h * s.a[k];  // v at n+1/2
    s.q[k] += h * s.v[k];
  }
  force_.project(h, s.q, s.v);
  s.t += h;
  force_.evaluate(s.t, s.q, s.v, h, s.f);
  for (size_t k = 0; k < n; ++k) {
    // a = f - w2 q - c (v_half + h/2 a), solved for a (diagonal damping).
    s.a[k] = (s.f[k] - w2_[k] * s.q[k] - c_[k] * s.v[k]) / (1.0 + 0.5 * h * c_[k]);
    s.v[k] += 0.5 * h * s.a[k];
  }
  dissipated_ += 0.5 * h * (p0 + dampingPower(s));
}

void ModalIntegrator::advance(ModalState& s, double dt, int substeps,
                              const std::function<void(double)>& onSubstep) const {
  const double t0 = s.t;
  const double h = dt / substeps;
  const auto reached = [&](double t, bool last) {
    if (onSubstep && !last) onSubstep(t);
  };
  for (int i = 0; i < substeps; ++i) {
    const double start = t0 + i * h;
    const bool lastStep = i + 1 == substeps;
    s.t = start;
    switch (scheme_) {
      case ModalScheme::SymplecticEuler:
        euler(s, h);
        ++subSteps_;
        reached(start + h, lastStep);
        break;
      case ModalScheme::CentralDifference:
        central(s, h);
        ++subSteps_;
        reached(start + h, lastStep);
        break;
      case ModalScheme::Adaptive: {
        const int r = force_.nearContact(h) ? refinement_ : 1;
        for (int j = 0; j < r; ++j) {
          s.t = start + j * (h / r);
          central(s, h / r);
          ++subSteps_;
          reached(start + (j + 1) * (h / r), lastStep && j + 1 == r);
        }
        break;
      }
    }
  }
  s.t = t0 + dt;  // no drift of the output times
}

void ModalIntegrator::archive(const ModalState& s, StateArchive& a) const {
  a.putDouble("modal/t", s.t);
  a.putVector("modal/q", s.q);
  a.putVector("modal/v", s.v);
  a.putVector("modal/a", s.a);
  a.putVector("modal/f", s.f);
  a.putInt("modal/substeps", subSteps_);
  a.putVector("modal/integrals", std::vector<double>{lastStep_, dissipated_});
  force_.archive(a);
}

void ModalIntegrator::restore(ModalState& s, const StateArchive& a) const {
  const size_t n = w2_.size();
  s.t = a.getDouble("modal/t");
  s.q = a.getVector<double>("modal/q", n);
  s.v = a.getVector<double>("modal/v", n);
  s.a = a.getVector<double>("modal/a", n);
  s.f = a.getVector<double>("modal/f", n);
  subSteps_ = a.getInt("modal/substeps");
  const std::vector<double> w = a.getVector<double>("modal/integrals", 2);
  lastStep_ = w[0];
  dissipated_ = w[1];
  force_.restore(a);
}

}  // namespace choc
