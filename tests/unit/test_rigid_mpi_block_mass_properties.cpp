// A mesh block's mass properties as a rigid body (src/rigid/BlockMassProperties.hpp): the 0.1 m
// steel cube of meshes/block_on_slab.msh (8 x 8 x 8 HEX8) against its closed forms, its
// elements summed on whichever rank holds them (1 and 2 ranks: the same to round-off).
#include <cmath>
#include <vector>

#include <gtest/gtest.h>
#include <Teuchos_DefaultComm.hpp>

#include "mesh/MeshFile.hpp"
#include "rigid/BlockMassProperties.hpp"

namespace choc {
namespace {

TEST(MpiBlockMassProperties, TheMeshedCubeHasItsClosedForms) {
  const Mesh mesh = readMeshFile(std::string(CHOC_SOURCE_DIR) + "/meshes/block_on_slab.msh");
  int cube = -1;
  for (size_t b = 0; b < mesh.blocks.size(); ++b)
    if (mesh.blocks[b].name == "block") cube = int(b);
  ASSERT_GE(cube, 0);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  // every element of the mesh dealt to the ranks in turn
  std::vector<int> mine;
  for (int e = comm->getRank(); e < mesh.numElements(); e += comm->getSize()) mine.push_back(e);
  const MassProperties p = blockMassProperties(mesh, {cube}, {7800.0}, Kinematics::ThreeD, mine, *comm);
  const double a = 0.1, m = 7800.0 * a * a * a;
  EXPECT_NEAR(p.mass, m, 1e-13 * m);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.centre[i], a / 2, 1e-15);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.moments[i], m * a * a / 6, 1e-13 * m * a * a);
  for (int k : {1, 2, 3, 5, 6, 7}) EXPECT_NEAR(p.inertia[size_t(k)], 0.0, 1e-14 * m * a * a);  // the cube's axes
  // a block of no mass: refused
  EXPECT_THROW(blockMassProperties(mesh, {cube}, {0.0}, Kinematics::ThreeD, mine, *comm), std::invalid_argument);
}

}  // namespace
}  // namespace choc
