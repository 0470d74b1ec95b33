// Cross-section properties of a beam, in the beam's local frame (x along the axis).
#pragma once
#include "mesh/Mesh.hpp"

namespace choc {

struct BeamSection {
  double area = 0.0;             // A [m^2]
  double Iy = 0.0;               // second moment about local y (bending in the x-z plane, DZ/DRY)
  double Iz = 0.0;               // second moment about local z (bending in the x-y plane, DY/DRZ)
  double torsionConstant = 0.0;  // J [m^4] (Saint-Venant torsion stiffness is G*J)
  double shearCoefficientY = 5.0 / 6.0;  // kappa for shear along local y (pairs with Iz)
  double shearCoefficientZ = 5.0 / 6.0;  // kappa for shear along local z (pairs with Iy)
  // Direction of the local y axis (need not be unit or orthogonal to the axis; its component
  // along the axis is removed). Zero: global y, or global z when the beam is along y.
  Point3 orientation = {0.0, 0.0, 0.0};

  // Polar second moment, used for the torsional (and lumped rotational) inertia.
  double polarInertia() const { return Iy + Iz; }
};

// A solid square section of side a: A = a^2, Iy = Iz = a^4/12, J = 0.1406 a^4.
inline BeamSection squareSection(double side) {
  BeamSection s;
  const double a2 = side * side;
  s.area = a2;
  s.Iy = s.Iz = a2 * a2 / 12.0;
  s.torsionConstant = 0.1406 * a2 * a2;
  return s;
}

}  // namespace choc
