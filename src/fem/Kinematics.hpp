// The kinematic assumption of a continuum element: full 3D, plane strain (unit thickness in
// z), or axisymmetric (x = radius r, y = axial coordinate z, integrals over the full ring).
#pragma once

namespace choc {

enum class Kinematics { ThreeD, PlaneStrain, Axisymmetric };

inline const char* toString(Kinematics k) {
  switch (k) {
    case Kinematics::ThreeD:
      return "3D";
    case Kinematics::PlaneStrain:
      return "plane strain";
    case Kinematics::Axisymmetric:
      return "axisymmetric";
  }
  return "?";
}

}  // namespace choc
