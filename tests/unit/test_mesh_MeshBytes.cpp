// A mesh survives the trip through bytes (how a mesh read in a child process comes back), and
// cut or altered bytes are refused, never read past.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "mesh/BarImpactMesh.hpp"
#include "mesh/MeshBytes.hpp"
#include "test_mesh_helpers.hpp"

namespace {

TEST(MeshBytes, RoundTripKeepsEverything) {
  for (int dimension : {1, 3}) {
    choc::BarImpactOptions o;
    o.dimension = dimension;
    const choc::Mesh a = choc::generateBarImpactMesh(o);
    const choc::Mesh b = choc::meshFromBytes(choc::meshToBytes(a));
    EXPECT_EQ(a.title, b.title);
    EXPECT_EQ(a.dimension, b.dimension);
    expectSameMesh(a, b);
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
