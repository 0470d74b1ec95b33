// The directions a contact constrains at each node of the contact surfaces, for 'Contact Mass' =
// normal (fem/NormalMassRemoval.hpp): at a node of a side set, the surface's normal (the faces
// around it, weighted by their area); at a node of a node set, the obstacle's normal at the node
// or the node-to-node pair's fixed normal. A node on two surfaces whose normals differ (the edge
// of a block pressed into a corner) is constrained along both. Directions are taken in the
// reference configuration and within the node's unknowns (a component fixed by a Dirichlet
// condition is removed from them first, so that a symmetry plane keeps its meaning).
#pragma once
#include <vector>

#include "fem/DofMap.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

class ContactManager;

// Per mesh node: an orthonormal set of directions (empty off the contact surfaces). Of the
// eigenvectors of S = sum over the node's pairs of the area-weighted mean of n n^T, those whose
// eigenvalue is at least a quarter of the largest: a curved surface's spread of normals (a few
// degrees per element) stays one direction, two faces at a right angle give two.
std::vector<std::vector<Point3>> contactNormalDirections(const ContactManager& contact, const Mesh& mesh,
                                                         const DofMap& dofs);

}  // namespace choc
