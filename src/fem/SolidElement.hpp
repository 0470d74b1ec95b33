// Isoparametric continuum elements, isotropic linear elasticity, small strain.
//
//   ThreeD        TET4 TET10 HEX8 HEX20; components {DX, DY, DZ}.
//   PlaneStrain   TRI3 TRI6 QUAD4 QUAD8 in the (x, y) plane (z ignored); components
//                 {DX, DY}; matrices per unit thickness.
//   Axisymmetric  TRI3 TRI6 QUAD4 QUAD8 with x = radius r >= 0, y = axial coordinate z;
//                 components {DX (radial), DY (axial)}; strains (e_rr, e_zz,
//                 e_thetatheta = u_r / r, gamma_rz); every integral carries 2 pi r, so the
//                 matrices are those of the full 360-degree ring. Nodes may lie on the axis.
//
// Element DOFs are node-major (ElementKernel.hpp). Quadrature: ShapeFunctions.hpp.
// Mass: consistent = rho N^T N per component (block-diagonal by component). Lumped: row sums
// of the consistent mass for TET4 HEX8 TRI3 QUAD4; HRZ (the consistent diagonal scaled to
// the element mass, per component) for TET10 HEX20 TRI6 QUAD8, whose row sums are not
// positive at every node. Both keep the element mass.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "fem/ElementKernel.hpp"
#include "fem/Kinematics.hpp"
#include "fem/Material.hpp"

namespace choc {

// Throws std::invalid_argument for an unknown topology, a topology that does not fit the
// kinematics (message naming both), E <= 0, nu outside (-1, 0.5) or density < 0. The
// kernel's stiffness() and mass() throw std::invalid_argument for a wrong node count, for
// det J <= 0 at a quadrature point or (quadratic topologies) det J < 0 at a corner node
// ("inverted or degenerate <TOPO> element: ..."), and, when axisymmetric, for a node with
// r < 0 or a quadrature point with r <= 0 ("axisymmetric elements need x = r >= 0 ...").
std::unique_ptr<ElementKernel> makeSolidElement(const std::string& topology, Kinematics kinematics,
                                                const Material& material);

// The element's measure by the mass quadrature: volume (ThreeD), area = volume per unit
// thickness (PlaneStrain), or the ring volume 2 pi int r dA (Axisymmetric). Same checks as
// the kernel.
double solidElementMeasure(const std::string& topology, Kinematics kinematics,
                           const std::vector<Point3>& x);

}  // namespace choc
