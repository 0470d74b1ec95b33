// Isotropic linear elastic material.
#pragma once

namespace choc {

struct Material {
  double youngsModulus = 0.0;  // E [Pa]
  double poissonsRatio = 0.0;  // nu [-]
  double density = 0.0;        // rho [kg/m^3]
  double shearModulus() const { return youngsModulus / (2.0 * (1.0 + poissonsRatio)); }
};

}  // namespace choc
