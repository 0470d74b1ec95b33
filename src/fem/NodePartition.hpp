// The nodes' partition among MPI ranks: Zoltan2's recursive coordinate bisection (RCB) of
// the node coordinates, each node weighted by its number of unknowns, so that ranks own
// compact regions of the scene whatever the mesh's numbering. Every rank computes the same
// partition on its own (the mesh is replicated; RCB on one process is deterministic). The
// DofMap then numbers the nodes part by part (ascending node index inside a part).
#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/Mesh.hpp"

namespace choc {

struct NodePartition {
  std::vector<int> order;      // the nodes, part 0's first
  std::vector<int> rankBegin;  // part r is order[rankBegin[r] .. rankBegin[r + 1])
  std::vector<int> partOf;     // per node
};

// One part: the identity order. Throws std::runtime_error if Zoltan2 fails.
NodePartition partitionNodes(const Mesh& mesh, const std::vector<std::uint8_t>& freeMask, int numParts);

struct PartitionQuality {
  std::vector<long long> dofsPerPart;
  double imbalance = 1.0;  // largest part's DOFs / mean
  long long sharedNodes = 0;  // nodes of an element that spans several parts
};
PartitionQuality partitionQuality(const Mesh& mesh, const std::vector<std::uint8_t>& freeMask,
                                  const NodePartition& p);

}  // namespace choc
