// Johnson and Cook's failure strain (formula and range in the header).
#include "materials/JohnsonCookDamage.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace choc {

namespace {

void require(bool ok, const char* name, double value, const char* range) {
  if (ok && std::isfinite(value)) return;
  std::ostringstream s;
  s << "Johnson-Cook damage: needs '" << name << "' " << range << ", got " << value;
  throw std::invalid_argument(s.str());
}

}  // namespace

JohnsonCookDamage::JohnsonCookDamage(const JohnsonCookDamageParameters& d, const JohnsonCookParameters& flow)
    : d_(d), flow_(flow) {
  if (!d.enabled) return;
  require(d.D1 >= 0, "Johnson-Cook D1", d.D1,
          ">= 0 (a negative D1 makes the failure strain negative at high triaxiality)");
  require(d.D2 >= 0, "Johnson-Cook D2", d.D2, ">= 0");
  require(d.D1 + d.D2 > 0, "Johnson-Cook D2", d.D2, "> 0 when D1 is 0 (the failure strain in shear is D1 + D2)");
  require(std::isfinite(d.D3), "Johnson-Cook D3", d.D3, "finite");
  require(d.D4 >= 0, "Johnson-Cook D4", d.D4, ">= 0");
  require(d.D5 >= 0, "Johnson-Cook D5", d.D5, ">= 0");
}

double JohnsonCookDamage::failureStrain(double triaxiality, double dalpha, double dt, double temperature) const {
  const double stress = d_.D1 + d_.D2 * std::exp(d_.D3 * triaxiality);
  const double rate = 1 + d_.D4 * johnsonCookLogRate(flow_, dalpha, dt);
  return stress * rate * (1 + d_.D5 * johnsonCookHomologous(flow_, temperature));
}

}  // namespace choc
