// The 'auto' linear solver's choice (src/solvers/SolverChoice.hpp): each rule on both sides of
// its threshold, and the stiffness-to-mass ratio of small matrices against hand computation.
#include <gtest/gtest.h>

#include <cmath>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "solvers/SolverChoice.hpp"

namespace choc {
namespace {

SolverRegime regime(long long n, double theta, const std::string& notSpd = "") {
  SolverRegime r;
  r.unknowns = n;
  r.stiffnessToMass = theta;
  r.notSymmetricBecause = notSpd;
  return r;
}

TEST(SolverChoice, SmallProblemsAreDirect) {
  EXPECT_EQ(chooseLinearSolver(regime(kAlwaysDirectUpTo, 1.0)).method, "Direct");
  const SolverChoice c = chooseLinearSolver(regime(kAlwaysDirectUpTo + 1, 1.0));
  EXPECT_EQ(c.method, "CG");
  EXPECT_EQ(c.preconditioner, "Jacobi");
  EXPECT_NE(c.reason.find("mass-dominated"), std::string::npos) << c.reason;
}

// A tangent that changes at every Newton iteration (finite strain) refactors at every solve: the
// size below which Direct is taken whatever the regime drops to kChangingTangentDirectUpTo.
TEST(SolverChoice, AChangingTangentIsDirectOnlyWhenSmall) {
  SolverRegime r = regime(kChangingTangentDirectUpTo, 1.0);
  r.tangentChanges = true;
  EXPECT_EQ(chooseLinearSolver(r).method, "Direct");
  r.unknowns = kChangingTangentDirectUpTo + 1;
  const SolverChoice c = chooseLinearSolver(r);
  EXPECT_EQ(c.method, "CG");
  EXPECT_EQ(c.preconditioner, "Jacobi");
  r.stiffnessToMass = 10 * kJacobiUpTo;  // stiffness-dominated: Direct up to kDirectUpTo
  EXPECT_EQ(chooseLinearSolver(r).method, "Direct");
  r = regime(kChangingTangentDirectUpTo + 1, 1.0, "contact friction");
  r.tangentChanges = true;
  EXPECT_EQ(chooseLinearSolver(r).method, "Direct");  // not symmetric: Direct at any size
}

TEST(SolverChoice, MatricesThatAreNotSpdAreDirectAtAnySize) {
  const SolverChoice c = chooseLinearSolver(regime(10 * kDirectUpTo, 1.0, "contact method 'Lagrange' has multipliers"));
  EXPECT_EQ(c.method, "Direct");
  EXPECT_NE(c.reason.find("multipliers"), std::string::npos) << c.reason;
}

TEST(SolverChoice, MatricesThatAreNotSpdTakeTheDistributedPackageAboveTheSmallSize) {
  SolverRegime small = regime(kAlwaysDirectUpTo, 1.0, "contact friction");
  small.distributedDirect = "MUMPS";
  EXPECT_EQ(chooseLinearSolver(small).package, "");  // the input's (KLU2)
  SolverRegime large = regime(kAlwaysDirectUpTo + 1, 1.0, "contact friction");
  EXPECT_EQ(chooseLinearSolver(large).package, "");  // no distributed package in this build
  large.distributedDirect = "MUMPS";
  const SolverChoice c = chooseLinearSolver(large);
  EXPECT_EQ(c.method, "Direct");
  EXPECT_EQ(c.package, "MUMPS");
  EXPECT_NE(c.reason.find("MUMPS factors it on every rank"), std::string::npos) << c.reason;
  // A symmetric positive definite matrix keeps its rules; its direct solves are the distributed
  // package's too, its iterative ones have none.
  SolverRegime spd = regime(50000, 1e6);
  spd.distributedDirect = "MUMPS";
  EXPECT_EQ(chooseLinearSolver(spd).method, "Direct");
  EXPECT_EQ(chooseLinearSolver(spd).package, "MUMPS");
  SolverRegime mass = regime(50000, 1.0);
  mass.distributedDirect = "MUMPS";
  EXPECT_EQ(chooseLinearSolver(mass).method, "CG");
  EXPECT_EQ(chooseLinearSolver(mass).package, "");
}

// Friction against obstacles alone (the multipliers condensed): GMRES + Jacobi while
// mass-dominated, on both sides of the limit; the direct solve beyond it and at small sizes.
TEST(SolverChoice, NearlySymmetricFrictionIsGmresJacobiWhileMassDominated) {
  SolverRegime r = regime(2 * kAlwaysDirectUpTo, kJacobiUpTo, "contact friction");
  r.nearlySymmetric = true;
  SolverChoice c = chooseLinearSolver(r);
  EXPECT_EQ(c.method, "GMRES");
  EXPECT_EQ(c.preconditioner, "Jacobi");
  r.stiffnessToMass = 1.01 * kJacobiUpTo;
  EXPECT_EQ(chooseLinearSolver(r).method, "Direct");
  r = regime(kAlwaysDirectUpTo, 1.0, "contact friction");
  r.nearlySymmetric = true;
  EXPECT_EQ(chooseLinearSolver(r).method, "Direct");
  r = regime(2 * kAlwaysDirectUpTo, 1.0, "contact friction");  // between meshed bodies
  EXPECT_EQ(chooseLinearSolver(r).method, "Direct");
}

TEST(SolverChoice, StiffnessDominatedIsDirectThenJacobiThenMultigrid) {
  EXPECT_EQ(chooseLinearSolver(regime(50000, kJacobiUpTo)).preconditioner, "Jacobi");
  EXPECT_EQ(chooseLinearSolver(regime(50000, 1.01 * kJacobiUpTo)).method, "Direct");
  EXPECT_EQ(chooseLinearSolver(regime(kDirectUpTo, 1e6)).method, "Direct");
  // Beyond Direct's size: Jacobi while theta <= kLargeJacobiUpTo, Multigrid above.
  const SolverChoice j = chooseLinearSolver(regime(kDirectUpTo + 1, kLargeJacobiUpTo));
  EXPECT_EQ(j.method, "CG");
  EXPECT_EQ(j.preconditioner, "Jacobi");
  EXPECT_NE(j.reason.find("<= 10,000"), std::string::npos) << j.reason;
  EXPECT_EQ(chooseLinearSolver(regime(kDirectUpTo + 1, 1.01 * kLargeJacobiUpTo)).preconditioner, "Multigrid");
  const SolverChoice c = chooseLinearSolver(regime(kDirectUpTo + 1, 1e6));
  EXPECT_EQ(c.method, "CG");
  EXPECT_EQ(c.preconditioner, "Multigrid");
  // A row without mass (theta = +inf) is stiffness-dominated.
  EXPECT_EQ(chooseLinearSolver(regime(kDirectUpTo + 1, INFINITY)).preconditioner, "Multigrid");
  // Without node blocks to aggregate, Additive Schwarz.
  SolverRegime noBlocks = regime(kDirectUpTo + 1, 1e6);
  noBlocks.nodeBlocks = false;
  EXPECT_EQ(chooseLinearSolver(noBlocks).preconditioner, "Additive Schwarz");
}

// A 3-row chain, K = k [1 -1 0; -1 2 -1; 0 -1 1], and a diagonal mass.
RCP<CrsMatrix> matrix(const std::vector<std::vector<double>>& a) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(a.size(), 0, comm));
  auto A = rcp(new CrsMatrix(map, 3));
  for (size_t i = 0; i < a.size(); ++i)
    if (map->isNodeGlobalElement(GO(i)))
      for (size_t j = 0; j < a.size(); ++j)
        if (a[i][j] != 0.0) A->insertGlobalValues(GO(i), Teuchos::tuple<GO>(GO(j)), Teuchos::tuple<double>(a[i][j]));
  A->fillComplete();
  return A;
}

TEST(SolverChoice, StiffnessToMassRatioIsTheLargestRowRatio) {
  const double k = 3e8, m = 2.0;
  auto K = matrix({{k, -k, 0}, {-k, 2 * k, -k}, {0, -k, k}});
  // Row sums of |K|: 2k, 4k, 2k; masses m, m, 4m: the middle row holds the largest ratio.
  auto M = matrix({{m, 0, 0}, {0, m, 0}, {0, 0, 4 * m}});
  const double mCoef = 4e12, kCoef = 0.3;
  EXPECT_DOUBLE_EQ(stiffnessToMassRatio(*K, *M, mCoef, kCoef), kCoef * 4 * k / (mCoef * m));
  // A massless row with stiffness: +inf.
  auto M0 = matrix({{m, 0, 0}, {0, 0, 0}, {0, 0, m}});
  EXPECT_TRUE(std::isinf(stiffnessToMassRatio(*K, *M0, mCoef, kCoef)));
}

}  // namespace
}  // namespace choc
