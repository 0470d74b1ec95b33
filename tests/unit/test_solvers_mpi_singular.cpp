// Singular systems, on 1 and 2 ranks: every linear solver must say so on every rank, never
// report a converged solve (on 2 ranks, a rank left out of the failure would hang the test).
// setMatrix() may throw choc::NumericalError, or solve() must return converged == false with
// a message; the residual it reports must be the true one (not the solver's own estimate).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Errors.hpp"
#include "input/Validation.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {
namespace {

enum class Kind { FreeFree, ZeroRow };

// n x n. FreeFree: the stiffness of a free-free chain of springs (rows sum to zero, null
// space = constants). ZeroRow: a regular tridiagonal matrix whose middle row and column are 0.
RCP<CrsMatrix> singularMatrix(int n, Kind kind) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(n, 0, comm));
  auto A = rcp(new CrsMatrix(map, 3));
  const int mid = n / 2;
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO i = map->getGlobalElement(l);
    Teuchos::Array<GO> cols;
    Teuchos::Array<double> vals;
    if (kind == Kind::FreeFree) {
      const double diag = (i == 0 || i == n - 1) ? 1.0 : 2.0;
      cols.push_back(i), vals.push_back(diag);
      if (i > 0) cols.push_back(i - 1), vals.push_back(-1.0);
      if (i < n - 1) cols.push_back(i + 1), vals.push_back(-1.0);
    } else {
      if (i == mid) {
        cols.push_back(i), vals.push_back(0.0);
      } else {
        cols.push_back(i), vals.push_back(4.0);
        if (i > 0 && i - 1 != mid) cols.push_back(i - 1), vals.push_back(-1.0);
        if (i < n - 1 && i + 1 != mid) cols.push_back(i + 1), vals.push_back(-1.0);
      }
    }
    A->insertGlobalValues(i, cols(), vals());
  }
  A->fillComplete();
  return A;
}

// A right-hand side outside the range of A: no x gives a small residual.
void inconsistentLoad(MultiVector& b, int n, Kind kind) {
  b.putScalar(0.0);
  const GO at = kind == Kind::FreeFree ? 0 : n / 2;  // net force / load on the empty row
  if (b.getMap()->isNodeGlobalElement(at)) b.replaceGlobalValue(at, 0, 1.0);
}

void expectSingularReported(const std::string& method, Kind kind) {
  const int n = 24;
  auto A = singularMatrix(n, kind);
  MultiVector b(A->getRangeMap(), 1), x(A->getDomainMap(), 1);
  inconsistentLoad(b, n, kind);
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", method);
  p.set("Maximum Iterations", 200);
  auto solver = makeLinearSolver(p);
  try {
    solver->setMatrix(A);
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("singular"), std::string::npos) << e.what();
    return;  // reported at the factorisation
  }
  LinearSolveStatus st;
  ASSERT_NO_THROW(st = solver->solve(b, x)) << method;
  EXPECT_FALSE(st.converged) << method << " reports a converged solve of a singular system "
                             << "(relative residual " << st.relativeResidual << ")";
  EXPECT_FALSE(st.message.empty()) << method;
  // Whatever x is, ||b - A x|| / ||b|| of an inconsistent system stays away from 0.
  const double r = relativeResidual(*A, b, x);
  EXPECT_TRUE(!(r <= 1e-3)) << method << ": true residual " << r;
}

TEST(MpiSingularSystem, DirectFreeFree) { expectSingularReported("Direct", Kind::FreeFree); }
TEST(MpiSingularSystem, DirectZeroRow) { expectSingularReported("Direct", Kind::ZeroRow); }
TEST(MpiSingularSystem, CgFreeFree) { expectSingularReported("CG", Kind::FreeFree); }
TEST(MpiSingularSystem, GmresFreeFree) { expectSingularReported("GMRES", Kind::FreeFree); }
TEST(MpiSingularSystem, GmresZeroRow) { expectSingularReported("GMRES", Kind::ZeroRow); }

// The same solver on the regularised matrix converges: the failures above are about the
// matrix, not the set-up of the test.
TEST(MpiSingularSystem, RegularisedSystemConverges) {
  for (const std::string method : {"Direct", "CG", "GMRES"}) {
    const int n = 24;
    auto A0 = singularMatrix(n, Kind::FreeFree);
    auto A = rcp(new CrsMatrix(A0->getRowMap(), 3));
    for (size_t l = 0; l < A0->getRowMap()->getNodeNumElements(); ++l) {
      const GO i = A0->getRowMap()->getGlobalElement(l);
      size_t cnt = A0->getNumEntriesInGlobalRow(i), got = 0;
      Teuchos::Array<GO> cols(cnt);
      Teuchos::Array<double> vals(cnt);
      A0->getGlobalRowCopy(i, cols(), vals(), got);
      for (size_t k = 0; k < got; ++k)
        if (cols[k] == i) vals[k] += 0.5;  // a spring to ground on every node
      A->insertGlobalValues(i, cols(0, got), vals(0, got));
    }
    A->fillComplete();
    MultiVector b(A->getRangeMap(), 1), x(A->getDomainMap(), 1);
    inconsistentLoad(b, n, Kind::FreeFree);
    Teuchos::ParameterList p = linearSolverParameters();
    p.set("Method", method);
    auto solver = makeLinearSolver(p);
    solver->setMatrix(A);
    LinearSolveStatus st = solver->solve(b, x);
    EXPECT_TRUE(st.converged) << method << ": " << st.message;
    EXPECT_LT(relativeResidual(*A, b, x), 1e-8) << method;
  }
}

}  // namespace
}  // namespace choc
