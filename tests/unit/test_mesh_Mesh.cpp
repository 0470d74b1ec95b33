// Mesh queries: element location across blocks, side nodes (Exodus convention), lookups.
#include <gtest/gtest.h>

#include <stdexcept>

#include "mesh/Mesh.hpp"

namespace {

choc::Mesh twoBlockMesh() {
  choc::Mesh m;
  m.coords.resize(14);
  choc::ElementBlock hex;
  hex.name = "H";
  hex.id = 7;
  hex.topology = "HEX8";
  hex.nodesPerElement = 8;
  hex.connectivity = {10, 11, 12, 13, 0, 1, 2, 3};  // one element, distinct node labels
  choc::ElementBlock beams;
  beams.name = "B";
  beams.id = 3;
  beams.topology = "BEAM2";
  beams.nodesPerElement = 2;
  beams.connectivity = {4, 5, 5, 6, 6, 7};
  choc::ElementBlock empty;
  empty.name = "E";
  empty.topology = "HEX8";
  empty.nodesPerElement = 8;
  m.blocks = {hex, empty, beams};
  m.nodeSets.push_back({"NS", 1, {0, 1}});
  m.sideSets.push_back({"SS", 1, {0}, {6}});
  return m;
}

TEST(MeshQueries, CountsAndLookups) {
  const choc::Mesh m = twoBlockMesh();
  EXPECT_EQ(m.numNodes(), 14);
  EXPECT_EQ(m.numElements(), 4);
  EXPECT_EQ(m.blocks[1].numElements(), 0);
  ASSERT_NE(m.findBlock("B"), nullptr);
  EXPECT_EQ(m.findBlock("B")->id, 3);
  EXPECT_EQ(m.findBlock("nope"), nullptr);
  ASSERT_NE(m.findNodeSet("NS"), nullptr);
  EXPECT_EQ(m.findNodeSet("SS"), nullptr);
  ASSERT_NE(m.findSideSet("SS"), nullptr);
  EXPECT_EQ(m.blockNames(), (std::vector<std::string>{"H", "E", "B"}));
  EXPECT_EQ(m.nodeSetNames(), (std::vector<std::string>{"NS"}));
  EXPECT_EQ(m.sideSetNames(), (std::vector<std::string>{"SS"}));
}

TEST(MeshQueries, LocateElementSkipsEmptyBlocks) {
  const choc::Mesh m = twoBlockMesh();
  EXPECT_EQ(m.locateElement(0), std::make_pair(0, 0));
  EXPECT_EQ(m.locateElement(1), std::make_pair(2, 0));
  EXPECT_EQ(m.locateElement(3), std::make_pair(2, 2));
  EXPECT_THROW(m.locateElement(4), std::out_of_range);
  EXPECT_THROW(m.locateElement(-1), std::out_of_range);
}

TEST(MeshQueries, Hex8SideNodesFollowExodus) {
  const choc::Mesh m = twoBlockMesh();
  // connectivity positions 1..8 hold nodes 10,11,12,13,0,1,2,3
  EXPECT_EQ(m.sideNodes(0, 1), (std::vector<int>{10, 11, 1, 0}));
  EXPECT_EQ(m.sideNodes(0, 2), (std::vector<int>{11, 12, 2, 1}));
  EXPECT_EQ(m.sideNodes(0, 3), (std::vector<int>{12, 13, 3, 2}));
  EXPECT_EQ(m.sideNodes(0, 4), (std::vector<int>{10, 0, 3, 13}));
  EXPECT_EQ(m.sideNodes(0, 5), (std::vector<int>{10, 13, 12, 11}));
  EXPECT_EQ(m.sideNodes(0, 6), (std::vector<int>{0, 1, 2, 3}));
  EXPECT_THROW(m.sideNodes(0, 0), std::out_of_range);
  EXPECT_THROW(m.sideNodes(0, 7), std::out_of_range);
}

TEST(MeshQueries, Beam2SidesAreEndNodes) {
  const choc::Mesh m = twoBlockMesh();
  EXPECT_EQ(m.sideNodes(2, 1), (std::vector<int>{5}));
  EXPECT_EQ(m.sideNodes(2, 2), (std::vector<int>{6}));
  EXPECT_THROW(m.sideNodes(2, 3), std::out_of_range);
}

}  // namespace
