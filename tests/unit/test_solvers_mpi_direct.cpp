// Linear solvers on an assembled clamped bar, on any number of ranks: the solution of
// K u = f (unit end load) is the exact static one, u(x) = F x / (E A) (linear elements are
// nodally exact for this problem), for the direct (KLU2 gathered on rank 0, MUMPS on every
// rank) and the Krylov solvers.
#include <gtest/gtest.h>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "fem/Assembler.hpp"
#include "fem/Beam2Element.hpp"
#include "fem/FieldGather.hpp"
#include "input/Validation.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "solvers/FactorizationBackend.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {
namespace {

struct ClampedBar {
  Mesh mesh;
  std::unique_ptr<DofMap> dofs;
  std::unique_ptr<Assembler> assembler;
  double E = 2e11, A = 4e-4;
  ClampedBar() {
    BarImpactOptions o;
    o.dimension = 1;
    o.along1 = 7;
    o.along2 = 9;
    mesh = generateBarImpactMesh(o);
    Material m{E, 0.0, 7800.0};
    std::vector<BlockPhysics> phys(2);
    for (auto& p : phys) p.kernel = makeBeam2(m, squareSection(0.02));
    auto mask = Assembler::carriedComponents(mesh, phys);
    for (auto& b : mask) b &= 1u;  // DX only
    // Clamp D (bar 2) and tie nothing else: solve on bar 2 only, bar 1 is left free and
    // unloaded, so fix it too.
    for (int n : mesh.findNodeSet("D")->nodes) mask[n] = 0;
    for (int n : mesh.findNodeSet("POU1")->nodes) mask[n] = 0;
    auto comm = Teuchos::DefaultComm<int>::getComm();
    dofs = std::make_unique<DofMap>(mask, comm->getSize(), comm->getRank());
    assembler = std::make_unique<Assembler>(mesh, *dofs, phys, comm);
  }
};

void solveAndCheck(const std::string& method, const std::string& package = "KLU2", bool symmetric = false) {
  ClampedBar bar;
  auto K = bar.assembler->stiffness();
  MultiVector f(K->getRangeMap(), 1), u(K->getDomainMap(), 1);
  const int C = bar.mesh.findNodeSet("C")->nodes[0];
  const long long dC = bar.dofs->dof(C, 0);
  const double F = 1000.0;
  if (K->getRowMap()->isNodeGlobalElement(dC)) f.replaceGlobalValue(dC, 0, F);
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", method);
  p.set("Direct Package", package);
  p.set("Tolerance", 1e-12);
  auto solver = makeLinearSolver(p, symmetric);
  solver->setMatrix(K);
  LinearSolveStatus st = solver->solve(f, u);
  ASSERT_TRUE(st.converged) << st.message;
  EXPECT_LT(st.relativeResidual, 1e-10);
  if (package == "MUMPS") EXPECT_EQ(solver->description(), symmetric ? "MUMPS (LDL^T)" : "MUMPS (LU)");
  auto all = gatherAll(u, 0, *bar.dofs);
  // Bar 2 from C (x=0) to D (x=-1): load +F at C, u(x) = F (x + 1) / (E A).
  for (int n : bar.mesh.findNodeSet("POU2")->nodes) {
    const long long d = bar.dofs->dof(n, 0);
    if (d < 0) continue;
    const double x = bar.mesh.coords[n][0];
    EXPECT_NEAR(all[d], F * (x + 1.0) / (bar.E * bar.A), 1e-9 * F / (bar.E * bar.A));
  }
}

TEST(MpiLinearSolver, DirectKlu2MatchesExactStaticSolution) { solveAndCheck("Direct"); }
// MUMPS factors on every rank (tools/build/install-deps.sh installs libmumps-dev).
TEST(MpiLinearSolver, DirectMumpsMatchesExactStaticSolution) {
  ASSERT_TRUE(mumpsAvailable()) << "this build has no MUMPS (CMake found no libmumps-dev)";
  solveAndCheck("Direct", "MUMPS");
}
// The same matrix said to be symmetric: LDL^T on its lower triangle.
TEST(MpiLinearSolver, DirectMumpsSymmetricMatchesExactStaticSolution) {
  ASSERT_TRUE(mumpsAvailable()) << "this build has no MUMPS (CMake found no libmumps-dev)";
  solveAndCheck("Direct", "MUMPS", true);
}
TEST(MpiLinearSolver, CgMatchesExactStaticSolution) { solveAndCheck("CG"); }
TEST(MpiLinearSolver, GmresMatchesExactStaticSolution) { solveAndCheck("GMRES"); }

}  // namespace
}  // namespace choc
