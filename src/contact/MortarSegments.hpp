// Segment-to-segment (mortar) integration between one slave face and one master face: the
// dual shape functions of the slave face, and the integration points of the part of the slave
// face that the master face overlaps.
//
// Overlap: both faces are projected along the slave face's unit normal n0 at its centre onto
// the plane through that centre (3D faces), or onto the slave edge's line (edges of planar
// elements); the master polygon (its corner nodes) clips the slave polygon (Sutherland-Hodgman,
// both convex), the clipped polygon is cut into triangles from its first vertex, and each
// triangle carries Radon's 7-point rule (degree 5: the products of bilinear shape functions on
// flat faces integrate exactly); an overlap of edges carries 3-point Gauss. Each point is
// projected along n0 onto the slave face and onto the master face (Newton on the parameters).
// Exact for flat slave faces; a curved face is integrated on its projection.
//
// Dual shape functions (Wohlmuth 2000): Phi_a = sum_b A_ab N_b on each slave face with
// A = D M^-1, M_ab = int N_a N_b, D = diag(int N_a): biorthogonal, int Phi_a N_b = delta_ab
// int N_a, and sum_a Phi_a = 1. Linear slave faces only (TRI3, QUAD4, LINE2): the corner
// integrals of quadratic faces vanish and need a modified basis.
#pragma once
#include <vector>

#include "contact/ContactFaces.hpp"
#include "contact/MortarIntegration.hpp"
#include "fem/DenseMatrix.hpp"

namespace choc {

// The faces mortar takes as slaves: TRI3, QUAD4, LINE2.
bool mortarSlaveFace(const Face& f);

// A of the slave face (n x n, n its node count); axisymmetric: the area element of a ring
// (2 pi r). Throws std::invalid_argument for a face mortarSlaveFace rejects.
DenseMatrix dualBasis(const Face& slave, bool axisymmetric);
// Phi at a point where the face's shape functions are N.
std::vector<double> dualShapes(const DenseMatrix& A, const std::vector<double>& N);

using MortarPoint = mortar::MortarPointOf<double>;

// The integration points of the overlap; empty when the faces do not overlap, when the master
// face does not face the slave (normals not opposed), or when a projection fails.
std::vector<MortarPoint> mortarPoints(const Face& slave, const Face& master, bool axisymmetric);

// The unit outward normal of the face at its node a.
Point3 nodeNormal(const Face& f, int a);

}  // namespace choc
