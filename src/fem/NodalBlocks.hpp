// The unknowns regrouped node by node, every node with the same components, and the rigid-body
// modes on them: what algebraic multigrid for elasticity needs (MueLu's "number of equations"
// and near-null space, solvers/ElasticityMultigrid.hpp).
//
// The DofMap leaves fixed components out, so nodes carry different numbers of unknowns. Here
// every node that carries at least one unknown becomes a block of `blockSize` rows, one per
// component used anywhere in the model (DZ alone in a 1D bar scene, DX DY in 2D, DX DY DZ for
// solids, six with beams' rotations); a component fixed at that node is a row of its own,
// decoupled from the others. Blocks follow the DofMap's node order, so each rank owns the
// blocks of the nodes it owns, contiguously.
#pragma once
#include <cstdint>
#include <vector>

#include "core/Vec3.hpp"
#include "fem/DofMap.hpp"

namespace choc {

struct NodalBlocks {
  int blockSize = 0;
  std::vector<int> components;           // the component of each slot of a block
  long long numGlobalBlocks = 0;
  long long firstOwnedBlock = 0;
  int numOwnedBlocks = 0;
  std::vector<long long> blockRowOfDof;  // global DOF id -> blockSize * block + slot
  std::vector<Vec3> ownedCoordinates;    // the node of each owned block
  // Per owned block row (numOwnedBlocks * blockSize): the global DOF it holds, -1 when fixed.
  std::vector<long long> ownedDofOfRow;

  // Rigid-body modes: a translation along each translational component used, a rotation
  // about each axis whose two perpendicular translations are used (its rotational
  // component too when present), about the owned nodes' centroid. Column-major on the owned
  // block rows: mode m's value at owned row i is modes[m * numOwnedRows() + i].
  int numRigidModes() const;
  std::vector<double> rigidBodyModes() const;
  long long numOwnedRows() const { return (long long)numOwnedBlocks * blockSize; }
};

// Every rank computes the whole DOF-to-row table (8 bytes per unknown).
NodalBlocks nodalBlocks(const DofMap& dofs, const std::vector<Vec3>& coords);

}  // namespace choc
