// The element topologies choc reads, with Exodus II conventions: node counts, the dimension
// of the element (1 beam, 2 planar element of a 2D mesh, 3 solid), and each side's nodes in
// Exodus side numbering (corners first, counter-clockwise seen from outside the element, then
// the mid-side nodes of quadratic sides). Sides of a solid are faces (TRI3, TRI6, QUAD4,
// QUAD8), sides of a planar element edges (LINE2, LINE3), sides of a beam its end points.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace choc {

struct Topology {
  std::string name;          // canonical: BEAM2, TET4, TET10, HEX8, HEX20, TRI3, TRI6, QUAD4, QUAD8
  int dimension = 0;         // 1, 2 or 3
  int numNodes = 0;
  std::string sideTopology;  // POINT, LINE2, LINE3, TRI3, TRI6, QUAD4, QUAD8 (per side below)
  std::vector<std::vector<int>> sides;  // side k (1-based) -> sides[k-1]: 0-based local nodes
  std::vector<std::string> sideTopologies;  // per side (a solid's sides may differ)
  int numCorners = 0;                        // the first nodes; the others are mid-edge nodes
  std::vector<std::pair<int, int>> midEdges;  // node numCorners + i sits between these corners
  int numSides() const { return static_cast<int>(sides.size()); }
};

// nullptr when `canonical` is not a topology choc knows.
const Topology* findTopology(const std::string& canonical);

// The canonical name of an Exodus element type (case-insensitive, with the aliases Exodus
// writers use: TETRA, TETRA10, HEX, HEXAHEDRON, TRI, TRIANGLE, QUAD, BAR2, TRUSS...) for the
// given node count, or "" when unsupported (shells, pyramids, wedges, a count that does not
// match the type).
std::string canonicalTopology(const std::string& exodusType, int nodesPerElement);

// "supported: BEAM2 (...), TET4, ..." for messages.
const std::string& supportedTopologiesText();

}  // namespace choc
