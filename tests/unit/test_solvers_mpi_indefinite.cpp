// CG on a symmetric matrix that is not positive definite (a finite-strain tangent under strong
// compression can be one): CG breaks down on p.Ap <= 0, and the iterative solver solves the
// same system by GMRES with the same preconditioner (solvers/IterativeSolver.cpp), on 1 and 2
// ranks. The solve must converge to the tolerance on the true residual and say so in the
// solver's description; a positive definite matrix must not take that path.
#include <gtest/gtest.h>

#include <string>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "input/Validation.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {
namespace {

// The chain Laplacian tridiag(-1, 2, -1) shifted by -shift I: its eigenvalues are
// 2 - 2 cos(k pi / (n + 1)) - shift, in (-shift, 4 - shift): indefinite for 0 < shift < 4.
RCP<CrsMatrix> shiftedChain(int n, double shift) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(n, 0, comm));
  auto A = rcp(new CrsMatrix(map, 3));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO i = map->getGlobalElement(l);
    Teuchos::Array<GO> cols;
    Teuchos::Array<double> vals;
    cols.push_back(i), vals.push_back(2.0 - shift);
    if (i > 0) cols.push_back(i - 1), vals.push_back(-1.0);
    if (i < n - 1) cols.push_back(i + 1), vals.push_back(-1.0);
    A->insertGlobalValues(i, cols(), vals());
  }
  A->fillComplete();
  return A;
}

std::string solveByCg(double shift, const std::string& preconditioner, double& residual) {
  const int n = 40;
  auto A = shiftedChain(n, shift);
  MultiVector b(A->getRangeMap(), 1), x(A->getDomainMap(), 1);
  b.putScalar(1.0);
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", "CG");
  p.set("Preconditioner", preconditioner);
  auto solver = makeLinearSolver(p);
  solver->setMatrix(A);
  const LinearSolveStatus st = solver->solve(b, x);
  EXPECT_TRUE(st.converged) << preconditioner << ": " << st.message;
  residual = relativeResidual(*A, b, x);
  return solver->description();
}

TEST(MpiIndefiniteSystem, CgBreakdownSolvedByGmres) {
  for (const std::string prec : {"None", "Jacobi"}) {
    double r = 1.0;
    const std::string d = solveByCg(1.3, prec, r);
    EXPECT_LE(r, 1e-9) << prec;  // 'Tolerance' 1e-10, the true residual within 10 times it
    EXPECT_NE(d.find("GMRES for 1 indefinite"), std::string::npos) << prec << ": " << d;
  }
}

TEST(MpiIndefiniteSystem, PositiveDefiniteStaysCg) {
  double r = 1.0;
  const std::string d = solveByCg(-0.5, "Jacobi", r);
  EXPECT_LE(r, 1e-9);
  EXPECT_EQ(d.find("GMRES"), std::string::npos) << d;
}

}  // namespace
}  // namespace choc
