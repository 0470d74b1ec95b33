// What the J2 family of laws ('J2 plasticity', 'Johnson-Cook') share: the parameters read from
// the common keys, and the point built from them.
#pragma once
#include <memory>

#include "materials/J2Plasticity.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {

// E, nu, the linear hardening keys and the kinematic hardening (refused in finite strain, naming
// in.block).
J2Parameters j2Parameters(const LawInput& in, bool finiteStrain);
// The J2Plasticity point of p; its range errors as InputError on the material.
std::shared_ptr<const MaterialPoint> j2LawPoint(const LawInput& in, const J2Parameters& p, bool finiteStrain);

}  // namespace choc
