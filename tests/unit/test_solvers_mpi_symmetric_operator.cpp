// SymmetricOperator (run on 1 and 2 ranks): the Krylov solvers' operator from half of a
// symmetric matrix's entries gives the matrix's product to round-off, with Belos' alpha and
// beta; CG + Jacobi through it solves a large symmetric system, and again after the matrix's
// values change on the same graph (the refill a change of contact status makes).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "input/Validation.hpp"
#include "solvers/LinearSolver.hpp"
#include "solvers/SymmetricOperator.hpp"
#include "relative_difference.hpp"
#include "symmetric_band_helpers.hpp"

namespace choc {
namespace {

using band::bandMatrix;
using band::noEdit;

const GO kLarge = GO(SymmetricProduct::kWorthwhileRows) + 1;

TEST(MpiSymmetricOperator, BuiltFromTheWorthwhileSizeOnly) {
  EXPECT_TRUE(SymmetricOperator::build(bandMatrix(GO(SymmetricProduct::kWorthwhileRows) - 1, 3, noEdit)).is_null());
  EXPECT_FALSE(SymmetricOperator::build(bandMatrix(kLarge, 3, noEdit)).is_null());
}

TEST(MpiSymmetricOperator, AppliesAlphaAXPlusBetaY) {
  auto A = bandMatrix(kLarge, 4, noEdit);
  auto op = SymmetricOperator::build(A);
  ASSERT_FALSE(op.is_null());
  for (const auto& ab : std::vector<std::pair<double, double>>{{1.0, 0.0}, {2.0, -0.5}, {-1.0, 1.0}, {0.5, 0.0}}) {
    const long long bad = band::rowsOutsideRoundoff(
        *A, [&](const Vector& x, Vector& y) { op->apply(x, y, Teuchos::NO_TRANS, ab.first, ab.second); },
        ab.first, ab.second);
    EXPECT_EQ(bad, 0) << "alpha " << ab.first << ", beta " << ab.second;
  }
}

// b = A x_e; CG + Jacobi must return x_e to the tolerance times A's condition number (the band
// matrix's diagonal 10 to 10.4 against off-diagonal rows summing to at most 2.7 in magnitude:
// Gershgorin gives eigenvalues in [7.3, 13.1], condition at most 1.8).
double solveError(LinearSolver& solver, const CrsMatrix& A, LinearSolveStatus& st) {
  MultiVector xe(A.getDomainMap(), 1), b(A.getRangeMap(), 1), x(A.getDomainMap(), 1);
  for (size_t l = 0; l < xe.getLocalLength(); ++l)
    xe.replaceLocalValue(LO(l), 0, band::probe(A.getRowMap()->getGlobalElement(LO(l))));
  A.apply(xe, b);
  st = solver.solve(b, x);
  return relativeDifference(x, xe);
}

TEST(MpiSymmetricOperator, CgSolvesThroughItAndAfterARefill) {
  auto A = bandMatrix(kLarge, 4, noEdit);
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", "CG");
  p.set("Preconditioner", "Jacobi");
  const double tol = p.get<double>("Tolerance");
  auto solver = makeLinearSolver(p);
  solver->setMatrix(A);
  LinearSolveStatus st;
  EXPECT_LE(solveError(*solver, *A, st), 1.8 * 10.0 * tol);
  EXPECT_TRUE(st.converged) << st.message;
  // New values on the same graph (diagonal 10 to 13): a stale product would solve the old
  // matrix, whose solution is far from x_e, and its true residual on A would fail the check.
  A->resumeFill();
  A->scale(1.3);
  A->fillComplete();
  solver->setMatrix(A);
  EXPECT_LE(solveError(*solver, *A, st), 1.8 * 10.0 * tol);
  EXPECT_TRUE(st.converged) << st.message;
}

}  // namespace
}  // namespace choc
