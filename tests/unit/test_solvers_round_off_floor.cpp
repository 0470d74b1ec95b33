// A regular but ill-conditioned system whose residual cannot reach the direct solver's
// tolerance: the clamped-free chain's stiffness squared, A = K^2 (K = L^T L, L the first
// difference with x_0 = 0; K^-1 = min(i, j)), the discrete beam of a slender solid in bending
// (cond(A) ~ (4 n^2 / pi^2)^2 = 1.3e9 at n = 300). Under an end load b = e_n its solution is
// known exactly, x = K^-1 K^-1 e_n: x_i = sum_j min(i, j) j. The round-off of A x alone is eps
// || |A| |x| || = 4e-8 of ||b||, above the tolerance 1e-8: the solve is accepted at that floor
// (DirectSolver's atRoundoffFloor), and its error is within what the conditioning allows,
// cond(A) times 1,000 eps (the floor's own factor). The singular systems that must still fail
// are test_solvers_mpi_singular.cpp's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "input/Validation.hpp"
#include "solvers/LinearSolver.hpp"

namespace choc {
namespace {

constexpr int kN = 300;

// K = tridiag(-1, 2, -1) with K_nn = 1 (1-based), and A = K K (pentadiagonal).
double kEntry(int i, int j) {
  if (i == j) return i == kN ? 1.0 : 2.0;
  return std::abs(i - j) == 1 ? -1.0 : 0.0;
}

RCP<CrsMatrix> squaredChain(const RCP<const Map>& map) {
  auto A = rcp(new CrsMatrix(map, 5));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO g = map->getGlobalElement(LO(l));
    const int i = int(g) + 1;
    Teuchos::Array<GO> cols;
    Teuchos::Array<double> vals;
    for (int j = std::max(1, i - 2); j <= std::min(kN, i + 2); ++j) {
      double s = 0.0;
      for (int k = std::max(1, i - 1); k <= std::min(kN, i + 1); ++k) s += kEntry(i, k) * kEntry(k, j);
      if (s != 0.0) cols.push_back(GO(j - 1)), vals.push_back(s);
    }
    A->insertGlobalValues(g, cols(), vals());
  }
  A->fillComplete();
  return A;
}

TEST(DirectSolverFloor, AnIllConditionedRegularSystemIsSolvedToItsConditioning) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  if (comm->getSize() != 1) GTEST_SKIP() << "the exact solution is compared on one rank";
  auto map = rcp(new Map(kN, 0, comm));
  auto A = squaredChain(map);
  MultiVector b(map, 1), x(map, 1), exact(map, 1);
  b.replaceGlobalValue(GO(kN - 1), 0, 1.0);
  // x_i = sum_j min(i, j) j, and ||A^-1||_inf = max_i sum_j (M^2)_ij with M = min(i, j).
  std::vector<double> m1(kN + 1, 0.0);
  for (int i = 1; i <= kN; ++i)
    for (int j = 1; j <= kN; ++j) m1[size_t(i)] += std::min(i, j);
  double inverseNorm = 0.0;
  for (int i = 1; i <= kN; ++i) {
    double xi = 0.0, row = 0.0;
    for (int j = 1; j <= kN; ++j) xi += double(std::min(i, j)) * j, row += std::min(i, j) * m1[size_t(j)];
    exact.replaceGlobalValue(GO(i - 1), 0, xi);
    inverseNorm = std::max(inverseNorm, row);
  }
  const double cond = A->getFrobeniusNorm() * std::sqrt(double(kN)) * inverseNorm;  // >= the infinity-norm one
  const double eps = std::numeric_limits<double>::epsilon();
  const double tol = 1e-8;
  // The floor exists: the exact solution's own product errs by more than the tolerance allows.
  ASSERT_GT(eps * productTermsRatio(*A, b, exact), tol);

  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", "Direct");
  p.set("Tolerance", tol);
  auto solver = makeLinearSolver(p, true);
  solver->setMatrix(A);
  const LinearSolveStatus st = solver->solve(b, x);
  EXPECT_TRUE(st.converged) << st.message;
  EXPECT_LE(st.relativeResidual, 1e-4);
  x.update(-1.0, exact, 1.0);
  std::vector<double> err(1), ref(1);
  x.normInf(Teuchos::ArrayView<double>(err));
  exact.normInf(Teuchos::ArrayView<double>(ref));
  EXPECT_LE(err[0] / ref[0], 1000 * eps * cond)
      << "relative error " << err[0] / ref[0] << ", cond " << cond << ", residual " << st.relativeResidual;
}

}  // namespace
}  // namespace choc
