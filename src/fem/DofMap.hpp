// Which nodal components are unknowns, their global numbering and their owner rank.
// A component is an unknown when an element at the node carries it, the model makes it
// active, and no Dirichlet condition fixes it: a 1D scene carries 1D unknowns and fixed DOFs
// are not in the system. Numbering is node-major; each rank owns a contiguous range of nodes
// (hence of DOFs), balanced by DOF count. Every rank holds the whole map (small: 2 ints/node).
#pragma once
#include <cstdint>
#include <vector>

namespace choc {

class DofMap {
 public:
  // freeMask[node]: bit c set when component c of node is an unknown.
  DofMap(std::vector<std::uint8_t> freeMask, int numRanks, int rank);

  long long numGlobal() const { return numGlobal_; }
  int numOwned() const { return static_cast<int>(ownedEnd_ - ownedBegin_); }
  long long firstOwned() const { return ownedBegin_; }
  int ownedNodeBegin() const { return nodeBegin_; }
  int ownedNodeEnd() const { return nodeEnd_; }
  bool ownsNode(int node) const { return node >= nodeBegin_ && node < nodeEnd_; }
  int numNodes() const { return static_cast<int>(mask_.size()); }

  bool isFree(int node, int comp) const { return (mask_[node] >> comp) & 1u; }
  std::uint8_t freeMask(int node) const { return mask_[node]; }
  // Global DOF id of (node, comp), or -1 when that component is not an unknown.
  long long dof(int node, int comp) const;
  // Owner rank of a node.
  int ownerOfNode(int node) const;

 private:
  std::vector<std::uint8_t> mask_;
  std::vector<long long> first_;  // first DOF id of each node (size numNodes+1)
  std::vector<int> rankNodeBegin_;  // size numRanks+1
  long long numGlobal_ = 0, ownedBegin_ = 0, ownedEnd_ = 0;
  int nodeBegin_ = 0, nodeEnd_ = 0;
};

}  // namespace choc
