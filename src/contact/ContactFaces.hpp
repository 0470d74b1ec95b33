// The faces of a contact surface and their geometry: QUAD4, QUAD8, TRI3, TRI6 faces of solids,
// LINE2 / LINE3 edges of planar elements (2D and axisymmetric meshes, in the x-y plane). An edge
// is a "face" with one parameter: its second tangent is e_z, so that dxi x e_z is the outward
// normal of a counter-clockwise element and |dxi x e_z| the length element.
#pragma once
#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include "fem/ShapeFunctions.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

// Geometry of one QUAD4 face: position and tangents at (xi, eta).
struct QuadPoint {
  Point3 x{}, dxi{}, deta{};
  std::array<double, 4> N{};
};
QuadPoint evaluateQuad(const std::array<Point3, 4>& corners, double xi, double eta);
// Closest point of x on the bilinear face; returns false when Gauss-Newton does not converge.
bool projectOnQuad(const std::array<Point3, 4>& corners, const Point3& x, double& xi, double& eta);

struct Face {
  std::vector<int> nodes;
  std::vector<Point3> x;  // the nodes' positions (reference, or current after a move)
  SolidShape shape = SolidShape::Quad4;
  int edgeNodes = 0;  // 2 (LINE2) or 3 (LINE3) for an edge, 0 for a face
};

// Position, tangents and shape functions of a face at (xi, eta).
struct FacePoint {
  Point3 x{}, dxi{}, deta{};
  std::vector<double> N;
};

// The faces of side set `name` at the mesh's reference coordinates. Throws
// std::invalid_argument when the set is missing, empty, or has sides that are not faces of
// solids or edges of planar elements.
std::vector<Face> facesOf(const Mesh& mesh, const std::string& name);
FacePoint evaluateFace(const Face& f, double xi, double eta);
// The face's shape functions at (xi, eta) with their first derivatives, dN[a] = {d/dxi, d/deta}
// (an edge: d/deta = 0).
void faceShapes(const Face& f, double xi, double eta, std::vector<double>& N, std::vector<std::array<double, 2>>& dN);
// Closest point of x on the face by Gauss-Newton from the face's centre; false when it does
// not converge.
bool projectOnFace(const Face& f, const Point3& x, double& xi, double& eta);
// (xi, eta) within the face's parameter domain, widened by tol.
bool insideFace(const Face& f, double xi, double eta, double tol = 1e-8);
bool isTriangle(const Face& f);

}  // namespace choc
