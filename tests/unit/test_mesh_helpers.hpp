// Helpers of the mesh tests.
#pragma once
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>

#include "mesh/Mesh.hpp"

// The same mesh with its nodes renumbered by a random permutation: new index = perm[old];
// elements and sets keep their order, their nodes follow.
inline choc::Mesh renumberedMesh(const choc::Mesh& m, unsigned seed, std::vector<int>* permutation = nullptr) {
  std::vector<int> perm(m.numNodes());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
  choc::Mesh r = m;
  for (int i = 0; i < m.numNodes(); ++i) r.coords[perm[i]] = m.coords[i];
  for (auto& b : r.blocks)
    for (int& n : b.connectivity) n = perm[n];
  for (auto& s : r.nodeSets)
    for (int& n : s.nodes) n = perm[n];
  if (permutation) *permutation = perm;
  return r;
}

// Same nodes, blocks, node sets and side sets (names, ids, topology, indices).
inline void expectSameMesh(const choc::Mesh& a, const choc::Mesh& b) {
  ASSERT_EQ(a.numNodes(), b.numNodes());
  for (int n = 0; n < a.numNodes(); ++n) EXPECT_EQ(a.coords[n], b.coords[n]) << "node " << n;
  ASSERT_EQ(a.blocks.size(), b.blocks.size());
  for (std::size_t i = 0; i < a.blocks.size(); ++i) {
    EXPECT_EQ(a.blocks[i].name, b.blocks[i].name);
    EXPECT_EQ(a.blocks[i].id, b.blocks[i].id);
    EXPECT_EQ(a.blocks[i].topology, b.blocks[i].topology);
    EXPECT_EQ(a.blocks[i].nodesPerElement, b.blocks[i].nodesPerElement);
    EXPECT_EQ(a.blocks[i].connectivity, b.blocks[i].connectivity);
  }
  ASSERT_EQ(a.nodeSets.size(), b.nodeSets.size());
  for (std::size_t i = 0; i < a.nodeSets.size(); ++i) {
    EXPECT_EQ(a.nodeSets[i].name, b.nodeSets[i].name);
    EXPECT_EQ(a.nodeSets[i].id, b.nodeSets[i].id);
    EXPECT_EQ(a.nodeSets[i].nodes, b.nodeSets[i].nodes);
  }
  ASSERT_EQ(a.sideSets.size(), b.sideSets.size());
  for (std::size_t i = 0; i < a.sideSets.size(); ++i) {
    EXPECT_EQ(a.sideSets[i].name, b.sideSets[i].name);
    EXPECT_EQ(a.sideSets[i].id, b.sideSets[i].id);
    EXPECT_EQ(a.sideSets[i].elements, b.sideSets[i].elements);
    EXPECT_EQ(a.sideSets[i].sides, b.sideSets[i].sides);
  }
}
