#include "mesh/Topology.hpp"

#include <algorithm>
#include <cctype>
#include <map>

#include "core/Format.hpp"

namespace choc {

namespace {

// 1-based node lists as the Exodus II manual gives them, converted to 0-based below.
using Sides = std::vector<std::vector<int>>;

Topology make(const std::string& name, int dim, int nodes, const Sides& sides1,
              const std::vector<std::string>& sideTopo,
              const std::vector<std::pair<int, int>>& midEdges = {}) {
  Topology t;
  t.midEdges = midEdges;
  t.numCorners = nodes - static_cast<int>(midEdges.size());
  t.name = name;
  t.dimension = dim;
  t.numNodes = nodes;
  for (const auto& s : sides1) {
    std::vector<int> z;
    for (int n : s) z.push_back(n - 1);
    t.sides.push_back(z);
  }
  t.sideTopologies = sideTopo.size() == 1 ? std::vector<std::string>(sides1.size(), sideTopo[0]) : sideTopo;
  t.sideTopology = t.sideTopologies.empty() ? "" : t.sideTopologies[0];
  return t;
}

const std::map<std::string, Topology>& table() {
  static const std::map<std::string, Topology> t = [] {
    std::map<std::string, Topology> m;
    auto add = [&](Topology x) { m[x.name] = std::move(x); };
    add(make("BEAM2", 1, 2, {{1}, {2}}, {"POINT"}));
    add(make("TET4", 3, 4, {{1, 2, 4}, {2, 3, 4}, {1, 4, 3}, {1, 3, 2}}, {"TRI3"}));
    add(make("TET10", 3, 10,
             {{1, 2, 4, 5, 9, 8}, {2, 3, 4, 6, 10, 9}, {1, 4, 3, 8, 10, 7}, {1, 3, 2, 7, 6, 5}},
             {"TRI6"}, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}));
    add(make("HEX8", 3, 8,
             {{1, 2, 6, 5}, {2, 3, 7, 6}, {3, 4, 8, 7}, {1, 5, 8, 4}, {1, 4, 3, 2}, {5, 6, 7, 8}},
             {"QUAD4"}));
    add(make("HEX20", 3, 20,
             {{1, 2, 6, 5, 9, 14, 17, 13},
              {2, 3, 7, 6, 10, 15, 18, 14},
              {3, 4, 8, 7, 11, 16, 19, 15},
              {1, 5, 8, 4, 13, 20, 16, 12},
              {1, 4, 3, 2, 12, 11, 10, 9},
              {5, 6, 7, 8, 17, 18, 19, 20}},
             {"QUAD8"},
             {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7}, {4, 5}, {5, 6}, {6, 7}, {7, 4}}));
    add(make("TRI3", 2, 3, {{1, 2}, {2, 3}, {3, 1}}, {"LINE2"}));
    add(make("TRI6", 2, 6, {{1, 2, 4}, {2, 3, 5}, {3, 1, 6}}, {"LINE3"}, {{0, 1}, {1, 2}, {2, 0}}));
    add(make("QUAD4", 2, 4, {{1, 2}, {2, 3}, {3, 4}, {4, 1}}, {"LINE2"}));
    add(make("QUAD8", 2, 8, {{1, 2, 5}, {2, 3, 6}, {3, 4, 7}, {4, 1, 8}}, {"LINE3"},
             {{0, 1}, {1, 2}, {2, 3}, {3, 0}}));
    return m;
  }();
  return t;
}

}  // namespace

const Topology* findTopology(const std::string& canonical) {
  const auto it = table().find(canonical);
  return it == table().end() ? nullptr : &it->second;
}

std::string canonicalTopology(const std::string& exodusType, int n) {
  const std::string t = upperTrimmed(exodusType);
  auto is = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* x) { return t == x; });
  };
  if (n == 2 && is({"BAR2", "BAR", "BEAM", "BEAM2", "TRUSS", "TRUSS2"})) return "BEAM2";
  if (n == 4 && is({"TETRA", "TETRA4", "TET4", "TET"})) return "TET4";
  if (n == 10 && is({"TETRA", "TETRA10", "TET10"})) return "TET10";
  if (n == 8 && is({"HEX", "HEX8", "HEXAHEDRON"})) return "HEX8";
  if (n == 20 && is({"HEX", "HEX20", "HEXAHEDRON"})) return "HEX20";
  if (n == 3 && is({"TRI", "TRI3", "TRIANGLE"})) return "TRI3";
  if (n == 6 && is({"TRI", "TRI6", "TRIANGLE"})) return "TRI6";
  if (n == 4 && is({"QUAD", "QUAD4", "QUADRILATERAL"})) return "QUAD4";
  if (n == 8 && is({"QUAD", "QUAD8", "QUADRILATERAL"})) return "QUAD8";
  return "";
}

const std::string& supportedTopologiesText() {
  static const std::string s =
      "supported: BEAM2 (also read from BAR2, BAR, BEAM, TRUSS, TRUSS2; 2 nodes), TET4 and "
      "TET10 (TETRA), HEX8 and HEX20 (HEX), TRI3 and TRI6 (TRI, TRIANGLE), QUAD4 and QUAD8 "
      "(QUAD; planar elements of a 2D mesh)";
  return s;
}

}  // namespace choc
