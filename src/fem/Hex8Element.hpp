// Eight-node trilinear hexahedron (Exodus HEX8 node order), isotropic linear elasticity,
// 3 DOF per node (DX DY DZ), full 2x2x2 Gauss integration.
#pragma once
#include <array>
#include <memory>

#include "fem/ElementKernel.hpp"
#include "fem/Material.hpp"

namespace choc {

using Hex8Gradients = std::array<std::array<double, 3>, 8>;  // dN_a/dx_i

// Shape-function gradients in global axes at the natural point xi (each in [-1, 1]) of the
// hexahedron with nodes x (8 points). Returns det J. Throws std::invalid_argument
// ("inverted or degenerate HEX8 ...") when det J <= 0.
double hex8Gradients(const std::vector<Point3>& x, const Point3& xi, Hex8Gradients& dNdx);

// The 2x2x2 Gauss points (natural coordinates); all weights are 1.
const std::array<Point3, 8>& hex8GaussPoints();

// Throws std::invalid_argument for E <= 0, nu outside (-1, 0.5) or density < 0.
std::unique_ptr<ElementKernel> makeHex8(const Material& material);

}  // namespace choc
