// Which nodal components are unknowns, their global numbering and their owner rank.
// A component is an unknown when an element at the node carries it, the model makes it
// active, and no Dirichlet condition fixes it: a 1D scene carries 1D unknowns and fixed DOFs
// are not in the system. Numbering is node-major along a node order; each rank owns a
// contiguous range of that order (hence of DOFs): by default the mesh's numbering cut into
// ranges balanced by DOF count, or a partition's order (NodePartition.hpp: Zoltan2). Every
// rank holds the whole map (small: 3 ints per node).
#pragma once
#include <cstdint>
#include <vector>

namespace choc {

class DofMap {
 public:
  // freeMask[node]: bit c set when component c of node is an unknown.
  DofMap(std::vector<std::uint8_t> freeMask, int numRanks, int rank);
  // The nodes numbered in `order` (a permutation of the nodes); rank r owns the positions
  // [rankBegin[r], rankBegin[r + 1]) of it.
  DofMap(std::vector<std::uint8_t> freeMask, const std::vector<int>& order,
         std::vector<int> rankBegin, int rank);

  long long numGlobal() const { return numGlobal_; }
  int numOwned() const { return static_cast<int>(ownedEnd_ - ownedBegin_); }
  long long firstOwned() const { return ownedBegin_; }
  bool ownsNode(int node) const { return pos_[node] >= nodeBegin_ && pos_[node] < nodeEnd_; }
  int numNodes() const { return static_cast<int>(mask_.size()); }

  bool isFree(int node, int comp) const { return (mask_[node] >> comp) & 1u; }
  std::uint8_t freeMask(int node) const { return mask_[node]; }
  // Global DOF id of (node, comp), or -1 when that component is not an unknown.
  long long dof(int node, int comp) const;
  // Owner rank of a node.
  int ownerOfNode(int node) const;
  // The node order: order()[p] is the node at position p; this rank owns the positions
  // [ownedPositionBegin(), ownedPositionEnd()).
  std::vector<int> order() const;
  int ownedPositionBegin() const { return nodeBegin_; }
  int ownedPositionEnd() const { return nodeEnd_; }

 private:
  std::vector<std::uint8_t> mask_;
  void number(const std::vector<int>& order);
  std::vector<long long> first_;    // first DOF id of each node
  std::vector<int> pos_;            // position of each node in the order
  std::vector<int> rankNodeBegin_;  // positions, size numRanks+1
  long long numGlobal_ = 0, ownedBegin_ = 0, ownedEnd_ = 0;
  int nodeBegin_ = 0, nodeEnd_ = 0;
};

}  // namespace choc
