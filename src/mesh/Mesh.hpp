// The in-memory mesh: what an Exodus II file holds that choc uses.
// Every rank holds the whole mesh (the benchmark meshes are small; see docs/performance/scale.md).
#pragma once
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "core/Vec3.hpp"

namespace choc {

using Point3 = Vec3;

// Exodus topology names as choc knows them: "BEAM2" (two-node beam/bar, also read from
// "BAR2", "BEAM", "TRUSS2", "BAR"), "HEX8" (also "HEX"), "QUAD4" (faces, not elements).
struct ElementBlock {
  std::string name;          // Exodus block name (e.g. POU1); "block_<id>" when unnamed
  int id = 0;                // Exodus block id
  std::string topology;      // canonical: "BEAM2" or "HEX8"
  int nodesPerElement = 0;
  std::vector<int> connectivity;  // 0-based node indices, nodesPerElement per element
  int numElements() const {
    return nodesPerElement ? static_cast<int>(connectivity.size()) / nodesPerElement : 0;
  }
};

struct NodeSet {
  std::string name;
  int id = 0;
  std::vector<int> nodes;  // 0-based node indices
};

// A side set: (element, side) pairs. Elements are 0-based global indices counting blocks in
// file order; sides are Exodus 1-based local side numbers (HEX8: 1..6, Exodus convention).
struct SideSet {
  std::string name;
  int id = 0;
  std::vector<int> elements;
  std::vector<int> sides;
};

struct Mesh {
  std::string title;
  int dimension = 3;              // spatial dimension of the coordinates (always 3 here)
  std::vector<Point3> coords;     // node coordinates
  std::vector<ElementBlock> blocks;
  std::vector<NodeSet> nodeSets;
  std::vector<SideSet> sideSets;

  int numNodes() const { return static_cast<int>(coords.size()); }
  int numElements() const;
  const NodeSet* findNodeSet(const std::string& name) const;     // nullptr when absent
  const SideSet* findSideSet(const std::string& name) const;
  const ElementBlock* findBlock(const std::string& name) const;
  // Block index and local element index of a global element index.
  std::pair<int, int> locateElement(int globalElement) const;
  // Node indices (0-based) of one side of an element, Exodus ordering (outward normal by
  // the right-hand rule for HEX8 faces).
  std::vector<int> sideNodes(int globalElement, int side) const;
  std::vector<std::string> nodeSetNames() const;
  std::vector<std::string> sideSetNames() const;
  std::vector<std::string> blockNames() const;
};

}  // namespace choc
