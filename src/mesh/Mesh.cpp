// Queries on the in-memory mesh (Mesh.hpp).
#include "mesh/Mesh.hpp"

#include <stdexcept>

#include "mesh/Topology.hpp"

namespace choc {

namespace {

template <class T>
const T* findByName(const std::vector<T>& items, const std::string& name) {
  for (const T& item : items)
    if (item.name == name) return &item;
  return nullptr;
}

template <class T>
std::vector<std::string> namesOf(const std::vector<T>& items) {
  std::vector<std::string> names;
  names.reserve(items.size());
  for (const T& item : items) names.push_back(item.name);
  return names;
}

}  // namespace

int Mesh::numElements() const {
  int n = 0;
  for (const ElementBlock& b : blocks) n += b.numElements();
  return n;
}

const NodeSet* Mesh::findNodeSet(const std::string& name) const {
  return findByName(nodeSets, name);
}

const SideSet* Mesh::findSideSet(const std::string& name) const {
  return findByName(sideSets, name);
}

const ElementBlock* Mesh::findBlock(const std::string& name) const {
  return findByName(blocks, name);
}

std::pair<int, int> Mesh::locateElement(int globalElement) const {
  if (globalElement >= 0) {
    int first = 0;
    for (int b = 0; b < static_cast<int>(blocks.size()); ++b) {
      const int n = blocks[b].numElements();
      if (globalElement < first + n) return {b, globalElement - first};
      first += n;
    }
  }
  throw std::out_of_range("mesh: element index " + std::to_string(globalElement) +
                          " out of range (mesh has " + std::to_string(numElements()) +
                          " elements)");
}

std::vector<int> Mesh::sideNodes(int globalElement, int side) const {
  const auto [b, e] = locateElement(globalElement);
  const ElementBlock& block = blocks[b];
  const int* conn = block.connectivity.data() +
                    static_cast<std::size_t>(e) * static_cast<std::size_t>(block.nodesPerElement);
  const Topology* topo = findTopology(block.topology);
  if (topo && side >= 1 && side <= topo->numSides()) {
    std::vector<int> nodes;
    for (int k : topo->sides[side - 1]) nodes.push_back(conn[k]);
    return nodes;
  }
  throw std::out_of_range("mesh: side " + std::to_string(side) + " of element " +
                          std::to_string(globalElement) + " (block '" + block.name +
                          "', topology " + block.topology + ") does not exist");
}

std::vector<std::string> Mesh::nodeSetNames() const { return namesOf(nodeSets); }
std::vector<std::string> Mesh::sideSetNames() const { return namesOf(sideSets); }
std::vector<std::string> Mesh::blockNames() const { return namesOf(blocks); }

}  // namespace choc
