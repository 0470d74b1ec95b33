// A mesh survives the trip through bytes (how a mesh read in a child process comes back), and
// cut or altered bytes are refused, never read past.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "mesh/BarImpactMesh.hpp"
#include "mesh/MeshBytes.hpp"

namespace {

TEST(MeshBytes, RoundTripKeepsEverything) {
  for (int dimension : {1, 3}) {
    choc::BarImpactOptions o;
    o.dimension = dimension;
    const choc::Mesh a = choc::generateBarImpactMesh(o);
    const choc::Mesh b = choc::meshFromBytes(choc::meshToBytes(a));
    EXPECT_EQ(a.title, b.title);
    EXPECT_EQ(a.dimension, b.dimension);
    EXPECT_EQ(a.coords, b.coords);
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
      EXPECT_EQ(a.sideSets[i].elements, b.sideSets[i].elements);
      EXPECT_EQ(a.sideSets[i].sides, b.sideSets[i].sides);
    }
  }
}

TEST(MeshBytes, CutOrAlteredBytesAreRefused) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  const std::string bytes = choc::meshToBytes(choc::generateBarImpactMesh(o));
  for (std::size_t keep = 0; keep < bytes.size(); keep += 13)
    EXPECT_THROW(choc::meshFromBytes(bytes.substr(0, keep)), std::runtime_error) << keep;
  EXPECT_THROW(choc::meshFromBytes(bytes + "x"), std::runtime_error);
  std::string huge = bytes;
  huge[15] = '\x7f';  // the title's length (little-endian 64-bit): 2^62 bytes
  EXPECT_THROW(choc::meshFromBytes(huge), std::runtime_error);
}

}  // namespace
