// Isoparametric shape functions of the continuum topologies, in Exodus II node order, and the
// quadrature rule each element uses.
//
// Reference cells and node order (1-based as in the Exodus II manual):
//   TET4   unit tetrahedron, nodes (0,0,0) (1,0,0) (0,1,0) (0,0,1).
//   TET10  TET4 plus mid-edge nodes 5..10 on edges (1,2) (2,3) (3,1) (1,4) (2,4) (3,4).
//   HEX8   [-1,1]^3: bottom face (zeta = -1) counter-clockwise seen from +zeta, then top face.
//   HEX20  HEX8 plus mid-edge nodes 9..12 on the bottom edges (1,2) (2,3) (3,4) (4,1),
//          13..16 on the vertical edges (1,5) (2,6) (3,7) (4,8), 17..20 on the top edges
//          (5,6) (6,7) (7,8) (8,5). Serendipity (no face or centre nodes).
//   TRI3   unit triangle, nodes (0,0) (1,0) (0,1).
//   TRI6   TRI3 plus mid-edge nodes 4..6 on edges (1,2) (2,3) (3,1).
//   QUAD4  [-1,1]^2, nodes counter-clockwise from (-1,-1).
//   QUAD8  QUAD4 plus mid-edge nodes 5..8 on edges (1,2) (2,3) (3,4) (4,1). Serendipity.
//
// Quadrature (see Quadrature.hpp for the rules). "Exact mass" means rho N_a N_b det J is
// integrated exactly on an affine (straight-sided parallelogram/parallelepiped or simplex)
// element, including the extra factor r of axisymmetric elements (one degree more).
//   topology  stiffness                         mass
//   TET4      1 point (B constant: exact)       4 points, degree 2 (N_a N_b is degree 2)
//   TET10     4 points, degree 2 (B^T D B is    14 points, degree 5, positive weights
//             degree 2: exact, full rank)       (N_a N_b is degree 4)
//   HEX8      2x2x2 Gauss (full rank)           2x2x2 Gauss (N_a N_b degree 2 per variable)
//   HEX20     3x3x3 Gauss (full rank; 2x2x2     3x3x3 Gauss (N_a N_b degree 4 per variable)
//             would leave spurious modes)
//   TRI3      1 point (exact); axisymmetric: 7  7 points, degree 5 (plane: degree 2 needed,
//             points (the hoop strain u_r/r     axisymmetric: 3)
//             varies; one point would leave a
//             zero-energy rotation mode)
//   TRI6      3 points, degree 2 (exact for     7 points, degree 5 (plane: degree 4 needed,
//             plane strain); axisymmetric: 7    axisymmetric: 5)
//             points
//   QUAD4     2x2 Gauss                         2x2 Gauss (degree 3 per variable >= 2 + 1)
//   QUAD8     3x3 Gauss                         3x3 Gauss (degree 5 per variable >= 4 + 1)
// All points lie strictly inside the cell, so the radius at a quadrature point of an
// axisymmetric element is positive even when nodes sit on the axis.
#pragma once
#include <string>
#include <vector>

#include "fem/Kinematics.hpp"
#include "fem/Quadrature.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

enum class SolidShape { Tet4, Tet10, Hex8, Hex20, Tri3, Tri6, Quad4, Quad8 };

// Canonical Exodus names of the supported continuum topologies: TET4 TET10 HEX8 HEX20 TRI3
// TRI6 QUAD4 QUAD8.
std::vector<std::string> solidTopologies();
const char* topologyName(SolidShape t);  // canonical name

// Case-insensitive lookup by an Exodus element type name, with the aliases Exodus writers
// use: TETRA/TETRA4/TET4, TETRA10/TET10, HEX/HEX8, HEX20, TRI/TRI3/TRIANGLE, TRI6,
// QUAD/QUAD4, QUAD8. Shells (SHELL4, ...) and beams are not solids. Returns false when the
// name is not a supported solid.
bool findSolidTopology(const std::string& name, SolidShape& topology);
// As findSolidTopology; throws std::invalid_argument naming the supported topologies.
SolidShape solidTopology(const std::string& name);

int nodeCount(SolidShape t);
int parametricDimension(SolidShape t);  // 3 for TET/HEX, 2 for TRI/QUAD
bool isQuadratic(SolidShape t);         // TET10 HEX20 TRI6 QUAD8
int cornerCount(SolidShape t);          // the vertices: nodes 1..cornerCount(t)

// Natural coordinates of the nodes (unused coordinates zero).
const std::vector<Point3>& nodeNaturalCoordinates(SolidShape t);

// Shape functions N[a] and their derivatives dN[a][i] = dN_a/dxi_i at the natural point xi
// (components beyond the parametric dimension are zero). Resizes N and dN to nodeCount(t).
void shapeFunctions(SolidShape t, const Point3& xi, std::vector<double>& N, std::vector<Point3>& dN);

const QuadratureRule& stiffnessRule(SolidShape t, Kinematics kinematics);
const QuadratureRule& massRule(SolidShape t);

}  // namespace choc
