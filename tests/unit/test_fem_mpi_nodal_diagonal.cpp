// The stiffest node's mean diagonal (fem/MatrixOps.hpp: largestNodalDiagonal, the default stick
// stiffness of friction) is the same in any frame the scene is drawn in, on any number of ranks:
// the trace of a node's diagonal block is unchanged by a rotation, where a single diagonal entry
// is not (the largest diagonal entry, the former default, changes with the frame).
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "fem/Assembler.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/MatrixOps.hpp"
#include "mesh/BarImpactMesh.hpp"

namespace choc {
namespace {

// K of the 3D bar-impact mesh (bar 2 free of Dirichlet conditions: every node has its 3
// components), its nodes turned by `angle` about (1, 2, 0.5) / |.|; (nodal, largest entry).
std::pair<double, double> diagonals(double angle) {
  BarImpactOptions o;
  o.dimension = 3;
  o.along1 = o.along2 = 6;
  o.across1 = o.across2 = 2;
  Mesh mesh = generateBarImpactMesh(o);
  const double s = std::sqrt(1.0 + 4.0 + 0.25);
  const double k[3] = {1.0 / s, 2.0 / s, 0.5 / s}, c = std::cos(angle), si = std::sin(angle);
  for (auto& X : mesh.coords) {  // Rodrigues: X c + (k x X) s + k (k.X)(1 - c)
    const double kx = k[0] * X[0] + k[1] * X[1] + k[2] * X[2];
    const double cx[3] = {k[1] * X[2] - k[2] * X[1], k[2] * X[0] - k[0] * X[2], k[0] * X[1] - k[1] * X[0]};
    for (int d = 0; d < 3; ++d) X[d] = X[d] * c + cx[d] * si + k[d] * kx * (1 - c);
  }
  std::vector<BlockPhysics> physics(mesh.blocks.size());
  for (auto& p : physics) p.kernel = makeHex8(Material{2e11, 0.3, 7800.0});
  const std::vector<std::uint8_t> mask = Assembler::carriedComponents(mesh, physics);
  auto comm = Teuchos::DefaultComm<int>::getComm();
  DofMap dofs(mask, comm->getSize(), comm->getRank());
  auto K = Assembler(mesh, dofs, physics, comm).stiffness({});
  return {largestNodalDiagonal(*K, dofs, 3), largestDiagonal(*K)};
}

TEST(MpiNodalDiagonal, TheStiffestNodeIsTheSameInATurnedFrame) {
  const auto [nodal, largest] = diagonals(0.0);
  const auto [nodalTurned, largestTurned] = diagonals(0.7);
  // Round-off of the element integrals (a few hundred terms of size |K|).
  EXPECT_NEAR(nodalTurned, nodal, 1e-12 * nodal);
  EXPECT_LE(nodal, largest);  // a mean of entries is at most the largest
  // The former default changes with the frame by far more than round-off (the check that the
  // turned scene is really turned).
  EXPECT_GT(std::abs(largestTurned - largest), 1e-3 * largest);
}

}  // namespace
}  // namespace choc
