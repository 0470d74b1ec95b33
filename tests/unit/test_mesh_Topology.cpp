// The Exodus side tables of every topology, checked on reference elements: each side's
// corners are ordered counter-clockwise seen from outside (outward normal by the right-hand
// rule), and each mid-side node of a quadratic side is the midpoint of the corners it sits
// between.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "core/Vec3.hpp"
#include "mesh/Topology.hpp"

namespace choc {
namespace {

std::vector<Vec3> withMidEdges(std::vector<Vec3> corners, const std::vector<std::pair<int, int>>& edges) {
  for (auto [a, b] : edges)
    corners.push_back({(corners[a][0] + corners[b][0]) / 2, (corners[a][1] + corners[b][1]) / 2,
                       (corners[a][2] + corners[b][2]) / 2});
  return corners;
}

// Reference node positions, Exodus order (0-based edges for the mid-edge nodes).
std::map<std::string, std::vector<Vec3>> referenceElements() {
  const std::vector<Vec3> tet = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const std::vector<Vec3> hex = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                 {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const std::vector<Vec3> tri = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const std::vector<Vec3> quad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  return {
      {"TET4", tet},
      {"TET10", withMidEdges(tet, {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}})},
      {"HEX8", hex},
      {"HEX20", withMidEdges(hex, {{0, 1}, {1, 2}, {2, 3}, {3, 0}, {0, 4}, {1, 5}, {2, 6}, {3, 7},
                                   {4, 5}, {5, 6}, {6, 7}, {7, 4}})},
      {"TRI3", tri},
      {"TRI6", withMidEdges(tri, {{0, 1}, {1, 2}, {2, 0}})},
      {"QUAD4", quad},
      {"QUAD8", withMidEdges(quad, {{0, 1}, {1, 2}, {2, 3}, {3, 0}})},
  };
}

Vec3 centroid(const std::vector<Vec3>& x, const std::vector<int>& nodes) {
  Vec3 c{0, 0, 0};
  for (int n : nodes)
    for (int i = 0; i < 3; ++i) c[i] += x[n][i] / nodes.size();
  return c;
}

TEST(Topology, SidesFaceOutwardAndMidSideNodesAreMidpoints) {
  for (const auto& [name, x] : referenceElements()) {
    const Topology* t = findTopology(name);
    ASSERT_NE(t, nullptr) << name;
    ASSERT_EQ(t->numNodes, int(x.size())) << name;
    std::vector<int> all(x.size());
    for (size_t i = 0; i < x.size(); ++i) all[i] = int(i);
    const Vec3 inside = centroid(x, all);
    for (int s = 0; s < t->numSides(); ++s) {
      const auto& side = t->sides[s];
      const int corners = t->dimension == 3 ? (side.size() == 3 || side.size() == 6 ? 3 : 4) : 2;
      std::vector<int> c(side.begin(), side.begin() + corners);
      const Vec3 mid = centroid(x, c);
      const Vec3 out = mid - inside;
      if (t->dimension == 3) {
        const Vec3 n = cross(x[c[1]] - x[c[0]], x[c[corners - 1]] - x[c[0]]);
        EXPECT_GT(dot(n, out), 0) << name << " side " << s + 1 << " points inwards";
      } else {  // an edge: outward normal (t_y, -t_x) for a counter-clockwise element
        const Vec3 tng = x[c[1]] - x[c[0]];
        EXPECT_GT(tng[1] * out[0] - tng[0] * out[1], 0) << name << " edge " << s + 1;
      }
      for (size_t k = corners; k < side.size(); ++k) {
        const int a = c[k - corners], b = c[(k - corners + 1) % corners];
        const Vec3 expect = centroid(x, {a, b});
        EXPECT_EQ(x[side[k]], expect) << name << " side " << s + 1 << " node " << k;
      }
    }
  }
}

TEST(Topology, MidEdgeNodesMatchTheReferenceElements) {
  for (const auto& [name, x] : referenceElements()) {
    const Topology* t = findTopology(name);
    ASSERT_EQ(t->numCorners + int(t->midEdges.size()), t->numNodes) << name;
    for (size_t i = 0; i < t->midEdges.size(); ++i) {
      const auto [a, b] = t->midEdges[i];
      EXPECT_EQ(x[t->numCorners + i], centroid(x, {a, b})) << name << " mid-edge node " << i;
    }
  }
}

TEST(Topology, SideCountsAndKinds) {
  EXPECT_EQ(findTopology("TET10")->numSides(), 4);
  EXPECT_EQ(findTopology("TET10")->sideTopology, "TRI6");
  EXPECT_EQ(findTopology("HEX20")->sideTopology, "QUAD8");
  EXPECT_EQ(findTopology("QUAD8")->sideTopology, "LINE3");
  EXPECT_EQ(findTopology("TRI3")->numSides(), 3);
  EXPECT_EQ(findTopology("BEAM2")->numSides(), 2);
  EXPECT_EQ(findTopology("WEDGE6"), nullptr);
}

}  // namespace
}  // namespace choc
