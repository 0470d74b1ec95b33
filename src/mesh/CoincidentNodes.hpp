// Nodes at the same place that no element shares: two parts meshed apart whose nodes meet
// (a gmsh geometry without "Coherence", two volumes exported separately) are not connected,
// and a body then falls through the other without a word. The model reports them once, and
// 'Mesh/Merge Coincident Nodes' joins them.
#pragma once
#include <utility>
#include <vector>

#include "mesh/Mesh.hpp"

namespace choc {

struct CoincidentNodes {
  std::vector<std::pair<int, int>> pairs;  // (kept node, duplicate), kept < duplicate, sorted
  double tolerance = 0;                    // distance below which two nodes coincide [m]
  int duplicates() const { return static_cast<int>(pairs.size()); }
};

// Nodes of elements closer than `relativeTolerance` times the shortest element edge to a node
// of another element they are not.
CoincidentNodes findCoincidentNodes(const Mesh& mesh, double relativeTolerance = 1e-6);

// Replaces every duplicate by the node it is kept for, in the elements' connectivity and in
// the node sets (each node once). The duplicates stay in the node list, on no element.
void mergeCoincidentNodes(Mesh& mesh, const CoincidentNodes& found);

}  // namespace choc
