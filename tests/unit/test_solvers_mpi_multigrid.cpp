// Multigrid for elasticity (solvers/ElasticityMultigrid, fem/NodalBlocks), on 1 and 2 ranks:
// the node-by-node regrouping holds every unknown once, the rigid-body modes are free of strain
// energy, and CG preconditioned by the hierarchy solves a stiffness-dominated system to the
// direct solver's answer in far fewer iterations than Jacobi.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <set>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/Assembler.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/MatrixOps.hpp"
#include "fem/NodalBlocks.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {
namespace {

struct Scene {
  Mesh mesh;
  std::unique_ptr<DofMap> dofs;
  RCP<CrsMatrix> K, M;
};

// The 3D bar-impact mesh: two bars of 3 x 3 x 30 cubic HEX8 (0.2 m long, section 0.02 x 0.02). clampFirstLayer: the first node layer
// of bar 1 loses DZ, and its first node DX and DY too (nodes with 1, 2 and 3 unknowns).
Scene scene(bool clampFirstLayer) {
  BarImpactOptions o;
  o.dimension = 3;
  o.along1 = o.along2 = 30;
  o.across1 = o.across2 = 3;
  o.length1 = o.length2 = 0.2;
  Scene s;
  s.mesh = generateBarImpactMesh(o);
  std::vector<BlockPhysics> physics(s.mesh.blocks.size());
  for (auto& p : physics) p.kernel = makeHex8(Material{2e11, 0.3, 7800.0});
  std::vector<std::uint8_t> mask = Assembler::carriedComponents(s.mesh, physics);
  if (clampFirstLayer) {
    for (int n = 0; n < 16; ++n) mask[n] &= ~(1u << 2);
    mask[0] = 0;  // no unknown left: not a block
    mask[1] = 1u;  // DX only
  }
  auto comm = Teuchos::DefaultComm<int>::getComm();
  s.dofs = std::make_unique<DofMap>(mask, comm->getSize(), comm->getRank());
  Assembler a(s.mesh, *s.dofs, physics, comm);
  s.K = a.stiffness({});
  s.M = a.mass();
  return s;
}

// v on K's map from a field on the owned block rows.
Vector onSystemRows(const NodalBlocks& b, const CrsMatrix& K, const double* rows) {
  Vector v(K.getRowMap());
  auto data = v.getDataNonConst();
  for (long long r = 0; r < b.numOwnedRows(); ++r) {
    const long long d = b.ownedDofOfRow[r];
    if (d >= 0) data[K.getRowMap()->getLocalElement(d)] = rows[r];
  }
  return v;
}

TEST(MpiMultigrid, BlocksHoldEveryUnknownOnceInRankOrder) {
  const Scene s = scene(true);
  const NodalBlocks b = nodalBlocks(*s.dofs, s.mesh.coords);
  EXPECT_EQ(b.blockSize, 3);
  EXPECT_EQ(b.numGlobalBlocks, s.mesh.numNodes() - 1);  // node 0 has no unknown
  std::set<long long> rows(b.blockRowOfDof.begin(), b.blockRowOfDof.end());
  EXPECT_EQ((long long)rows.size(), s.dofs->numGlobal());
  EXPECT_GE(*rows.begin(), 0);
  EXPECT_LT(*rows.rbegin(), b.numGlobalBlocks * b.blockSize);
  // The owned rows are this rank's DOFs, each once, and none other.
  long long held = 0;
  for (long long r = 0; r < b.numOwnedRows(); ++r) {
    const long long d = b.ownedDofOfRow[r];
    if (d < 0) continue;
    ++held;
    EXPECT_EQ(b.blockRowOfDof[d], b.firstOwnedBlock * b.blockSize + r);
    EXPECT_TRUE(d >= s.dofs->firstOwned() && d < s.dofs->firstOwned() + s.dofs->numOwned());
  }
  EXPECT_EQ(held, s.dofs->numOwned());
}

TEST(MpiMultigrid, RigidBodyModesCarryNoStrainEnergy) {
  const Scene s = scene(false);
  const NodalBlocks b = nodalBlocks(*s.dofs, s.mesh.coords);
  ASSERT_EQ(b.numRigidModes(), 6);
  const std::vector<double> modes = b.rigidBodyModes();
  const double kNorm = largestDiagonal(*s.K);
  for (int m = 0; m < 6; ++m) {
    const Vector v = onSystemRows(b, *s.K, &modes[m * b.numOwnedRows()]);
    Vector Kv(s.K->getRangeMap());
    s.K->apply(v, Kv);
    // Round-off of the element integrals: |K| |v| times a few hundred ulps.
    EXPECT_LE(Kv.normInf(), 1e-12 * kNorm * v.normInf()) << "mode " << m;
    // A mode that is not rigid (a swapped sign in a rotation) strains the body: the check can fail.
    if (m >= 3) {
      std::vector<double> wrong(modes.begin() + m * b.numOwnedRows(), modes.begin() + (m + 1) * b.numOwnedRows());
      for (long long i = 0; i < b.numOwnedBlocks; ++i) wrong[i * 3 + (m - 2) % 3] *= -1.0;
      const Vector w = onSystemRows(b, *s.K, wrong.data());
      s.K->apply(w, Kv);
      EXPECT_GT(Kv.normInf(), 1e-6 * kNorm * w.normInf()) << "mode " << m;
    }
  }
}

// W = K + c M at a stiffness-to-mass ratio of about 1e5 (the stiffness-dominated regime), with
// part of bar 1's first layer clamped.
LinearSolveStatus solveWith(const Scene& s, const std::string& preconditioner, Vector& x) {
  const double c = largestDiagonal(*s.K) / largestDiagonal(*s.M) / 1e5;
  RCP<CrsMatrix> W = addMatrices(1.0, *s.K, c, *s.M);
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", preconditioner.empty() ? "Direct" : "CG");
  if (!preconditioner.empty()) p.set("Preconditioner", preconditioner);
  p.set("Tolerance", 1e-10);
  p.set("Maximum Iterations", 1000);
  auto blocks = std::make_shared<const NodalBlocks>(nodalBlocks(*s.dofs, s.mesh.coords));
  auto solver = makeLinearSolver(p, true, blocks);
  solver->setMatrix(W);
  Vector b(W->getRangeMap());
  auto data = b.getDataNonConst();
  for (size_t i = 0; i < data.size(); ++i)  // a load spread over every unknown, varying
    data[i] = std::sin(0.37 * double(W->getRowMap()->getGlobalElement(LO(i))));
  x.putScalar(0.0);
  return solver->solve(b, x);
}

TEST(MpiMultigrid, CgWithTheHierarchySolvesAStiffSystemInFewIterations) {
  const Scene s = scene(true);
  Vector xm(s.K->getRowMap()), xj(s.K->getRowMap()), xd(s.K->getRowMap());
  const LinearSolveStatus mg = solveWith(s, "Multigrid", xm);
  const LinearSolveStatus jacobi = solveWith(s, "Jacobi", xj);
  const LinearSolveStatus direct = solveWith(s, "", xd);
  ASSERT_TRUE(mg.converged) << mg.message;
  std::printf("iterations: multigrid %d, Jacobi %d\n", mg.iterations, jacobi.iterations);
  ASSERT_TRUE(direct.converged) << direct.message;
  // Multigrid's iterations do not grow with the stiffness: within the 40 per solve the
  // stiffness-dominated scene needs (docs/performance/multigrid.md), and under half Jacobi's.
  EXPECT_LE(mg.iterations, 40);
  EXPECT_LT(2 * mg.iterations, jacobi.iterations);
  // The same answer as the direct solve, to the CG tolerance times the condition number's share.
  xm.update(-1.0, xd, 1.0);
  EXPECT_LE(xm.normInf(), 1e-6 * xd.normInf());
}

}  // namespace
}  // namespace choc
