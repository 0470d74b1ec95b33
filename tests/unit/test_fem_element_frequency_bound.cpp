// The element eigenvalue bound of the critical step (fem/ElementFrequencyBound.hpp): against the
// closed forms of the 2-node bar element and the lumped free chain, and as a bound of the
// assembled eigenvalues of distorted 3D meshes, which it must never fall below, and of
// Gershgorin's row sums, which it must not exceed there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "fem/Assembler.hpp"
#include "fem/Beam2Element.hpp"
#include "fem/Components.hpp"
#include "fem/ElementFrequencyBound.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/MatrixOps.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "test_fem_helpers.hpp"

using namespace choc;
using namespace choc::test;

namespace {

const Material kSteel{2e11, 0.0, 8000.0};  // nu = 0: c = sqrt(E / rho) = 5000 m/s in every bar
const double kC2 = 2e11 / 8000.0;

// The axial rows (DX at both nodes) of a BEAM2 along x of length h.
std::vector<char> axialOnly(int nodes, int nc) {
  std::vector<char> a(size_t(nodes) * nc, 0);
  for (int k = 0; k < nodes; ++k) a[k * nc] = 1;
  return a;
}

TEST(ElementFrequencyBound, TwoNodeBarGivesTheFreeChainsHighestEigenvalue) {
  const double h = 0.01;
  auto beam = makeBeam2(kSteel, squareSection(0.02));
  DenseMatrix K, M;
  const std::vector<Point3> x{{0, 0, 0}, {h, 0, 0}};
  beam->stiffness(x, K);
  beam->mass(x, MassKind::Lumped, M);
  const int nc = static_cast<int>(beam->components().size());
  // K = EA/h [1 -1; -1 1], M = rho A h / 2 I: the antisymmetric mode, lambda = 4 c^2 / h^2.
  EXPECT_NEAR(elementEigenvalue(K, M, axialOnly(2, nc)), 4 * kC2 / (h * h), 1e-12 * 4 * kC2 / (h * h));
  // One end fixed: the other node alone, lambda = (EA/h) / (rho A h / 2) = 2 c^2 / h^2.
  std::vector<char> one(size_t(2) * nc, 0);
  one[nc] = 1;
  EXPECT_NEAR(elementEigenvalue(K, M, one), 2 * kC2 / (h * h), 1e-12 * 2 * kC2 / (h * h));
  // No unknown: no frequency.
  EXPECT_EQ(elementEigenvalue(K, M, std::vector<char>(size_t(2) * nc, 0)), 0.0);
}

TEST(ElementFrequencyBound, DoesNotApplyToAConsistentOrMasslessElement) {
  auto hex = makeHex8(kSteel);
  const std::vector<Point3> x{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                              {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  DenseMatrix K, M;
  hex->stiffness(x, K);
  hex->mass(x, MassKind::Consistent, M);
  const std::vector<char> all(24, 1);
  EXPECT_TRUE(std::isinf(elementEigenvalue(K, M, all)));
  hex->mass(x, MassKind::Lumped, M);
  EXPECT_TRUE(std::isfinite(elementEigenvalue(K, M, all)));
  M(5, 5) = 0.0;  // a stiff row without mass: infinitely fast
  EXPECT_TRUE(std::isinf(elementEigenvalue(K, M, all)));
}

struct Scene {
  Mesh mesh;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<Assembler> assembler;
};

// SDNV100's bar (0.2 m along z, 0.02 x 0.02 m), n HEX8 along and `across` in each lateral
// direction, lumped mass; `axial`: DZ only (DX = DY = 0, the benchmark's 1D wave), else every
// component with the face z = 0 fixed along z. `jitter` moves every node at random by that
// fraction of the smallest element side (a distorted mesh).
Scene bar(int n, int across, bool axial, double jitter) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  o.length1 = 0.2;
  o.length2 = 0.01;
  o.along1 = n;
  o.along2 = 1;
  o.across1 = o.across2 = across;
  Scene s;
  s.mesh = generateBarImpactMesh(o);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-jitter, jitter);
  for (auto& p : s.mesh.coords)
    for (int c = 0; c < 3; ++c) p[c] += d(rng) * std::min(0.2 / n, 0.02 / across);
  std::vector<BlockPhysics> phys(s.mesh.blocks.size());
  for (auto& p : phys) {
    p.kernel = makeHex8(kSteel);
    p.mass = MassKind::Lumped;
  }
  auto mask = Assembler::carriedComponents(s.mesh, phys);
  for (int node : s.mesh.findNodeSet("POU2")->nodes) mask[node] = 0;  // bar 1 alone
  if (axial)
    for (auto& b : mask) b &= std::uint8_t(1u << DZ);
  else
    for (int node : s.mesh.findNodeSet("FACE_POU1")->nodes) mask[node] &= std::uint8_t(~(1u << DZ));
  auto comm = Teuchos::DefaultComm<int>::getComm();
  s.dofs = std::make_unique<DofMap>(mask, 1, 0);
  s.assembler = std::make_unique<Assembler>(s.mesh, *s.dofs, phys, comm);
  return s;
}

DenseMatrix dense(const CrsMatrix& A) {
  const int n = static_cast<int>(A.getGlobalNumRows());
  DenseMatrix D(n, n);
  RowCopy row;
  for (int i = 0; i < n; ++i) {
    row.read(A, GO(i));
    for (size_t k = 0; k < row.size; ++k) D(i, int(row.cols[k])) += row.vals[k];
  }
  return D;
}

// The largest eigenvalue of (K, M) and Gershgorin's bound of M^-1/2 K M^-1/2, M diagonal.
void assembled(const Scene& s, double& lambdaMax, double& gershgorin) {
  const DenseMatrix K = dense(*s.assembler->stiffness()), M = dense(*s.assembler->mass());
  const int n = K.rows();
  DenseMatrix A(n, n);
  gershgorin = 0.0;
  for (int i = 0; i < n; ++i) {
    double row = 0.0;
    for (int j = 0; j < n; ++j) {
      A(i, j) = K(i, j) / std::sqrt(M(i, i) * M(j, j));
      row += std::fabs(A(i, j));
    }
    gershgorin = std::max(gershgorin, row);
  }
  lambdaMax = symmetricEigenvalues(A).back();
}

TEST(ElementFrequencyBound, AxialBarIsExactlyTheFreeChain) {
  // DZ only, nu = 0: each HEX8 is a 2-node bar, the chain is free at z = 0.2 and at z = 0, and
  // its highest eigenvalue is 4 c^2 / h^2 exactly (omega_N = 2 c / h): the bound is exact.
  const int n = 20;
  const Scene s = bar(n, 1, true, 0.0);
  const double h = 0.2 / n, exact = 4 * kC2 / (h * h);
  const double bound = s.assembler->eigenvalueBound();
  EXPECT_NEAR(bound, exact, 1e-12 * exact);
  double lambda = 0, gersh = 0;
  assembled(s, lambda, gersh);
  EXPECT_NEAR(lambda, exact, 1e-9 * exact);
}

TEST(ElementFrequencyBound, BoundsTheAssembledEigenvaluesOfDistortedMeshes) {
  for (int across : {1, 2})
    for (double jitter : {0.0, 0.2}) {
      const Scene s = bar(6, across, false, jitter);
      const double bound = s.assembler->eigenvalueBound();
      double lambda = 0, gersh = 0;
      assembled(s, lambda, gersh);
      SCOPED_TRACE("across " + std::to_string(across) + ", jitter " + std::to_string(jitter));
      // An upper bound (to the Jacobi eigenvalues' round-off), whatever the distortion.
      EXPECT_GE(bound, lambda * (1 - 1e-10));
      std::printf("across %d, jitter %.1f: element bound / lambda_max %.4f, Gershgorin / lambda_max %.4f\n",
                  across, jitter, bound / lambda, gersh / lambda);
      // On a regular mesh tighter than Gershgorin's (on a distorted one either may be the
      // smaller: the critical step takes the smaller of the two).
      if (jitter == 0.0) {
        EXPECT_LT(bound, gersh);
      }
    }
}

TEST(ElementFrequencyBound, GroundedSpringsAddTheirOwnBound) {
  // A spring k along z at a node of mass m raises the bound by k / m (one row, one direction):
  // the bound stays above the assembled eigenvalue with the spring.
  const Scene s = bar(6, 1, true, 0.0);
  const int node = s.mesh.findNodeSet("B")->nodes.front();
  const double m = dense(*s.assembler->mass())(int(s.dofs->dof(node, DZ)), int(s.dofs->dof(node, DZ)));
  const double k = 1e12;
  const std::vector<NodalSpring> springs{{node, {0, 0, 1}, k}};
  EXPECT_NEAR(s.assembler->eigenvalueBound(springs), s.assembler->eigenvalueBound() + k / m,
              1e-12 * (s.assembler->eigenvalueBound() + k / m));
  const DenseMatrix K = dense(*s.assembler->stiffness(springs)), M = dense(*s.assembler->mass());
  DenseMatrix A(K.rows(), K.rows());
  for (int i = 0; i < K.rows(); ++i)
    for (int j = 0; j < K.rows(); ++j) A(i, j) = K(i, j) / std::sqrt(M(i, i) * M(j, j));
  EXPECT_GE(s.assembler->eigenvalueBound(springs), symmetricEigenvalues(A).back() * (1 - 1e-10));
}

}  // namespace
