// The dense eigen-solver against Anasazi and against the closed form of a lumped chain.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "fem/Assembler.hpp"
#include "fem/Beam2Element.hpp"
#include "core/Errors.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "solvers/DenseEigenSolver.hpp"

namespace choc {
namespace {

struct FreeBar {
  Mesh mesh;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<Assembler> assembler;
  explicit FreeBar(MassKind mass, int n = 20) {
    BarImpactOptions o;
    o.dimension = 1;
    o.along1 = n;
    o.along2 = 3;
    mesh = generateBarImpactMesh(o);
    std::vector<BlockPhysics> phys(2);
    for (auto& p : phys) {
      p.kernel = makeBeam2(Material{2e11, 0.0, 7800.0}, squareSection(0.02));
      p.mass = mass;
    }
    auto mask = Assembler::carriedComponents(mesh, phys);
    for (auto& b : mask) b &= 1u;                                // DX only
    for (int n2 : mesh.findNodeSet("POU2")->nodes) mask[n2] = 0;  // bar 1 alone, free-free
    auto comm = Teuchos::DefaultComm<int>::getComm();
    dofs = std::make_unique<DofMap>(mask, comm->getSize(), comm->getRank());
    assembler = std::make_unique<Assembler>(mesh, *dofs, phys, comm);
  }
};

// Lumped free-free chain of N equal elements: omega_k = (2c/h) sin(k pi / (2N)), k = 0..N.
TEST(MpiDenseEigen, CompleteBasisOfALumpedChainMatchesTheClosedForm) {
  const int N = 20;
  FreeBar bar(MassKind::Lumped, N);
  auto K = bar.assembler->stiffness();
  auto M = bar.assembler->mass();
  EigenRequest req;
  req.numModes = N + 1;  // every mode, which Krylov-Schur cannot give
  // The shift the modal analysis uses for 'Lowest': it also scales the residual of the
  // rigid-body mode (K phi = 0).
  req.shift = -1e-4 * K->getFrobeniusNorm() / M->getFrobeniusNorm();
  EigenResult r = solveDenseEigenproblem(K, M, req);
  ASSERT_EQ(int(r.eigenvalues.size()), N + 1);
  const double c = std::sqrt(2e11 / 7800.0), h = 1.0 / N;
  for (int k = 0; k <= N; ++k) {
    const double w = 2 * c / h * std::sin(k * M_PI / (2.0 * N));
    EXPECT_NEAR(r.eigenvalues[k], w * w, 1e-9 * (2 * c / h) * (2 * c / h)) << "mode " << k;
    EXPECT_NEAR(r.generalizedMass[k], 1.0, 1e-12);
    // Backward-stable solve: residual of order n eps relative to ||K phi||, and to
    // |sigma| ||M phi|| = 1e-4 (||K||/||M||) ||M phi|| for the rigid-body mode.
    EXPECT_LT(r.residuals[k], 1e4 * (N + 1) * 2.3e-16);
  }
  // M-orthonormal basis: Phi^T M Phi = I.
  MultiVector MPhi(M->getRangeMap(), N + 1);
  M->apply(*r.vectors, MPhi);
  for (int i = 0; i <= N; ++i)
    for (int j = 0; j <= N; ++j)
      EXPECT_NEAR(r.vectors->getVector(i)->dot(*MPhi.getVector(j)), i == j ? 1.0 : 0.0, 1e-12);
}

TEST(MpiDenseEigen, AgreesWithKrylovSchurOnTheLowestModes) {
  FreeBar bar(MassKind::Consistent);
  auto K = bar.assembler->stiffness();
  auto M = bar.assembler->mass();
  EigenRequest req;
  req.numModes = 8;
  req.shift = -1e7;  // below every eigenvalue: the lowest
  EigenResult d = solveDenseEigenproblem(K, M, req);
  EigenResult a = solveEigenproblem(K, M, req);
  for (int k = 1; k < 8; ++k)
    EXPECT_NEAR(d.eigenvalues[k], a.eigenvalues[k], 1e-9 * a.eigenvalues[k]) << "mode " << k;
  EXPECT_LT(std::abs(d.eigenvalues[0]), 1e-6 * d.eigenvalues[1]);  // rigid-body mode
}

TEST(DenseEigen, RefusesMoreModesThanUnknowns) {
  FreeBar bar(MassKind::Lumped, 5);
  EigenRequest req;
  req.numModes = 7;  // 6 unknowns
  EXPECT_THROW(solveDenseEigenproblem(bar.assembler->stiffness(), bar.assembler->mass(), req),
               InputError);
}

}  // namespace
}  // namespace choc
