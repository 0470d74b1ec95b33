// The mass properties of mesh blocks taken together as one rigid body: each rank sums its own
// elements of those blocks (MassPropertiesSum), the sums are added over the ranks, about the
// first node of the blocks' first element (the same point on every rank).
#pragma once
#include <utility>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/Kinematics.hpp"
#include "mesh/Mesh.hpp"
#include "rigid/MassProperties.hpp"

namespace choc {

// blocks: indices into mesh.blocks; densities: one per entry of blocks [kg/m^3]; elements: the
// global element indices this rank sums (each element on exactly one rank, e.g.
// Model::localElements()), those of other blocks skipped. Collective. Throws
// std::invalid_argument for blocks of no element or of no mass, or an inverted element.
// points: point masses (position, mass) this rank adds to the body (its share of them).
MassProperties blockMassProperties(const Mesh& mesh, const std::vector<int>& blocks,
                                   const std::vector<double>& densities, Kinematics kinematics,
                                   const std::vector<int>& elements, const Comm& comm,
                                   const std::vector<std::pair<Vec3, double>>& points = {});

}  // namespace choc
