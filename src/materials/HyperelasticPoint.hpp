// A hyperelastic law (Hyperelastic.hpp: S and dS/dE from C) as a material point: P = F S and
// A_iJkL = dP_iJ/dF_kL = delta_ik S_JL + F_iI F_kK CC_IJKL; no state, reported at F.
#pragma once
#include <memory>

#include "materials/Hyperelastic.hpp"
#include "materials/MaterialPoint.hpp"

namespace choc {

std::shared_ptr<const MaterialPoint> hyperelasticPoint(std::shared_ptr<const HyperelasticMaterial> law);

}  // namespace choc
