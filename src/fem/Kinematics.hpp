// The kinematic assumption of a continuum element: full 3D, plane strain (unit thickness in
// z), or axisymmetric (x = radius r, y = axial coordinate z, integrals over the full ring).
#pragma once
#include <stdexcept>
#include <string>

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

// The inverse of toString (the input's 'Model/Kinematics'); std::invalid_argument otherwise.
inline Kinematics kinematicsFromName(const std::string& name) {
  for (Kinematics k : {Kinematics::ThreeD, Kinematics::PlaneStrain, Kinematics::Axisymmetric})
    if (name == toString(k)) return k;
  throw std::invalid_argument("unknown kinematics '" + name + "'");
}

}  // namespace choc
