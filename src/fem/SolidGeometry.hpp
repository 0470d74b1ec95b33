// The reference geometry of the isoparametric continuum elements, shared by the small-strain
// (SolidElement) and the finite-strain (FiniteStrainSolid) kernels: node checks and the volume
// weight of a quadrature point.
#pragma once
#include <vector>

#include "fem/IsoparametricPoint.hpp"
#include "fem/Kinematics.hpp"
#include "fem/Quadrature.hpp"

namespace choc {

// Throws std::invalid_argument when the topology does not fit the kinematics (naming both).
void checkSolidKinematics(SolidShape t, Kinematics k);

// Checks the nodes before any integration: axisymmetric radii (x = r >= 0), and for the
// quadratic topologies det J at the corner nodes. Throws std::invalid_argument.
void validateSolidNodes(SolidShape t, Kinematics k, const std::vector<Point3>& x);

// Evaluates the map at quadrature point q of `rule` into p and returns w_q dV_q (times 2 pi r
// when axisymmetric). Throws std::invalid_argument for det J <= 0 or r <= 0 there.
double solidVolumeWeight(SolidShape t, Kinematics k, const std::vector<Point3>& x, const QuadratureRule& rule,
                         int q, IsoparametricPoint& p);

}  // namespace choc
