// The flow-stress laws (formulas in the header).
#include "materials/FlowStress.hpp"

#include <algorithm>
#include <limits>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace choc {

namespace {

[[noreturn]] void refuse(const std::string& law, const std::string& what) {
  throw std::invalid_argument(law + ": " + what);
}

std::string number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

FlowStress FlowStress::linear(double yieldStress, double hardening) {
  FlowStress f;
  f.yield_ = yieldStress;
  f.hardening_ = hardening;
  return f;
}

FlowStress FlowStress::curve(const FlowCurve& c) {
  const std::string law = "J2 plasticity material, 'Flow Curve'";
  if (c.strain.empty() || c.strain.size() != c.stress.size())
    refuse(law, "needs pairs 'strain stress', the first at strain 0");
  if (c.strain[0] != 0.0) refuse(law, "the first point's plastic strain is " + number(c.strain[0]) + ", not 0");
  if (!(c.stress[0] > 0)) refuse(law, "the initial yield stress is " + number(c.stress[0]) + " Pa, not > 0");
  for (size_t i = 1; i < c.strain.size(); ++i) {
    if (!(c.strain[i] > c.strain[i - 1]) || !std::isfinite(c.strain[i]))
      refuse(law, "the plastic strains must increase, but " + number(c.strain[i]) + " follows " +
                      number(c.strain[i - 1]));
    if (!(c.stress[i] >= c.stress[i - 1]) || !std::isfinite(c.stress[i]))
      refuse(law, "the flow stress must not decrease (softening is not supported), but " + number(c.stress[i]) +
                      " Pa follows " + number(c.stress[i - 1]) + " Pa");
  }
  FlowStress f;
  f.kind_ = Kind::Curve;
  f.curve_ = c;
  f.yield_ = c.stress[0];
  return f;
}

FlowStress FlowStress::johnsonCook(const JohnsonCookParameters& p) {
  const std::string law = "Johnson-Cook material";
  if (!(p.A > 0) || !std::isfinite(p.A)) refuse(law, "needs 'Johnson-Cook A' > 0 [Pa], got " + number(p.A));
  if (!(p.B >= 0) || !std::isfinite(p.B)) refuse(law, "needs 'Johnson-Cook B' >= 0 [Pa], got " + number(p.B));
  if (!(p.n > 0 && p.n <= 1)) refuse(law, "needs 'Johnson-Cook n' in (0, 1], got " + number(p.n));
  if (!(p.C >= 0) || !std::isfinite(p.C)) refuse(law, "needs 'Johnson-Cook C' >= 0, got " + number(p.C));
  if (!(p.referenceRate > 0) || !std::isfinite(p.referenceRate))
    refuse(law, "needs 'Reference Strain Rate' > 0 [1/s], got " + number(p.referenceRate));
  if (!(p.m > 0) || !std::isfinite(p.m)) refuse(law, "needs 'Johnson-Cook m' > 0, got " + number(p.m));
  if (!(p.meltingTemperature > p.referenceTemperature) || !std::isfinite(p.meltingTemperature))
    refuse(law, "needs 'Melting Temperature' above 'Reference Temperature' (" + number(p.referenceTemperature) +
                    "), got " + number(p.meltingTemperature));
  if (!(p.initialTemperature < p.meltingTemperature) || !std::isfinite(p.initialTemperature))
    refuse(law, "'Initial Temperature' " + number(p.initialTemperature) + " is at or above the melting temperature " +
                    number(p.meltingTemperature));
  if (!(p.taylorQuinney >= 0 && p.taylorQuinney <= 1))
    refuse(law, "needs 'Taylor-Quinney Coefficient' in [0, 1], got " + number(p.taylorQuinney));
  if (p.taylorQuinney > 0 && (!(p.specificHeat > 0) || !std::isfinite(p.specificHeat)))
    refuse(law, "needs 'Specific Heat' > 0 [J/(kg K)] for the adiabatic heating, got " + number(p.specificHeat));
  if (!(p.density > 0)) refuse(law, "needs a density > 0, got " + number(p.density));
  FlowStress f;
  f.kind_ = Kind::JohnsonCook;
  f.jc_ = p;
  f.yield_ = p.A;
  f.heatPerWork_ = p.taylorQuinney > 0 ? p.taylorQuinney / (p.density * p.specificHeat) : 0.0;
  return f;
}

double johnsonCookLogRate(const JohnsonCookParameters& p, double dalpha, double dt) {
  return dt > 0 && dalpha > 0 && dalpha > p.referenceRate * dt ? std::log(dalpha / (p.referenceRate * dt)) : 0.0;
}

double FlowStress::meltingTemperature() const {
  return kind_ == Kind::JohnsonCook ? jc_.meltingTemperature : std::numeric_limits<double>::infinity();
}

bool FlowStress::melted(double temperature) const {
  return kind_ == Kind::JohnsonCook && 1 - std::pow(johnsonCookHomologous(jc_, temperature), jc_.m) <= kMelted;
}

double johnsonCookHomologous(const JohnsonCookParameters& p, double temperature) {
  return std::clamp((temperature - p.referenceTemperature) / (p.meltingTemperature - p.referenceTemperature), 0.0, 1.0);
}

FlowStress::Value FlowStress::at(double alphaOld, double dalpha, double dt, double temperature) const {
  const double alpha = alphaOld + dalpha;
  Value v;
  if (kind_ == Kind::Linear) {
    v.stress = yield_ + hardening_ * alpha;
    v.slope = hardening_;
    return v;
  }
  if (kind_ == Kind::Curve) {
    const auto& e = curve_.strain;
    const auto& s = curve_.stress;
    const size_t i = size_t(std::upper_bound(e.begin(), e.end(), alpha) - e.begin());  // e[i-1] <= alpha < e[i]
    if (i >= e.size()) {
      v.stress = s.back();
      return v;
    }
    const size_t k = i == 0 ? 0 : i - 1;
    v.slope = (s[k + 1] - s[k]) / (e[k + 1] - e[k]);
    v.stress = s[k] + v.slope * (alpha - e[k]);
    return v;
  }
  const JohnsonCookParameters& p = jc_;
  const double power = alpha > 0 ? std::pow(alpha, p.n) : 0.0;
  const double hardening = p.A + p.B * power;
  const double dHardening = alpha > 0 ? p.n * p.B * power / alpha : (p.n == 1.0 ? p.B : 0.0);
  const double logRate = johnsonCookLogRate(p, dalpha, dt);
  const double rate = 1 + p.C * logRate, dRate = logRate > 0 ? p.C / dalpha : 0.0;
  const double thermal = 1 - std::pow(johnsonCookHomologous(p, temperature), p.m);
  v.stress = hardening * rate * thermal;
  v.slope = (dHardening * rate + hardening * dRate) * thermal;
  return v;
}

std::string FlowStress::describe() const {
  std::ostringstream s;
  if (kind_ == Kind::Linear)
    s << "linear hardening, sigma_y = " << yield_ << " Pa + " << hardening_ << " Pa alpha";
  else if (kind_ == Kind::Curve)
    s << "flow curve of " << curve_.strain.size() << " points, " << curve_.stress.front() << " to "
      << curve_.stress.back() << " Pa";
  else
    s << "Johnson-Cook flow stress (A = " << jc_.A << " Pa, B = " << jc_.B << " Pa, n = " << jc_.n << ", C = " << jc_.C
      << ", Reference Strain Rate = " << jc_.referenceRate << " 1/s, m = " << jc_.m << ")";
  return s.str();
}

}  // namespace choc
