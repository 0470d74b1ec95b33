// 'Contact Mass' = normal: the contact surfaces' nodes lose their mass only along the directions
// the contact constrains (their normals), and keep it along the surface. The element mass Me
// (nodes x, nc components per node, node-major) becomes T^T Me T with
//     u_k = P_k u~_k + N_k sum_j w_j u~_j,   N_k = sum_d d d^T over node k's directions, P_k = I - N_k,
// the j the nearest nodes of the element with no direction (equal weights w_j); other nodes
// u_k = u~_k. Hence M d_k = 0 for every direction d_k of a contact node (its normal carries no
// inertia), T 1 = 1 so each component's element mass is kept, and T^T Me T is symmetric positive
// semi-definite. A lumped matrix is lumped again by node blocks (sums over the columns' nodes)
// to stay block diagonal: diagonal where the normals follow the axes. The variant with every
// direction of a node is the Khenous-Laborde-Renard redistribution (redistributeElementMass).
// Throws std::invalid_argument when every node of the element has a direction.
#pragma once
#include <vector>

#include "fem/DenseMatrix.hpp"
#include "fem/ElementKernel.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

// directions[a]: node a's constrained unit directions (3D, orthonormal); comps: the spatial
// component of each of the element's nc components per node.
void removeNormalMass(const std::vector<Point3>& x, const std::vector<const std::vector<Point3>*>& directions,
                      const std::vector<int>& comps, MassKind kind, DenseMatrix& Me);

}  // namespace choc
