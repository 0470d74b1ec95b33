// ReplicatedSparseLU (the sparse factorisation of contact's Gram matrices): each rank factors
// the matrix it holds alone (KLU2 on MPI_COMM_SELF), so 2 ranks must give each the answer of a
// dense solve of the same matrix; a linearly dependent row is refused.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include <Teuchos_LAPACK.hpp>

#include "solvers/ReplicatedSparseLU.hpp"

namespace choc {
namespace {

using Entries = std::vector<ReplicatedSparseLU::Entry>;

// A nonsymmetric m x m matrix with the pattern of a chain of constraints (each coupled to its
// neighbours two away), diagonally dominant; some entries named twice (they sum).
Entries chain(int m, double skew) {
  Entries e;
  for (int i = 0; i < m; ++i) {
    e.push_back({i, i, 3.0 + 0.01 * i});
    for (int d : {1, 2})
      if (i + d < m) e.push_back({i, i + d, -0.5 / d + skew}), e.push_back({i + d, i, -0.5 / d - skew});
    if (i % 7 == 0) e.push_back({i, i, 0.25});
  }
  return e;
}

std::vector<double> denseSolve(int m, const Entries& entries, std::vector<double> b) {
  std::vector<double> A(size_t(m) * m, 0.0);
  for (const auto& e : entries) A[size_t(e.col) * m + e.row] += e.value;
  std::vector<int> pivots(static_cast<size_t>(m));
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  lapack.GETRF(m, m, A.data(), m, pivots.data(), &info);
  lapack.GETRS('N', m, 1, A.data(), m, pivots.data(), b.data(), m, &info);
  return b;
}

TEST(MpiReplicatedSparseLU, SolvesAsTheDenseFactorisation) {
  for (double skew : {0.0, 0.3}) {  // symmetric (G) and not (C^T V)
    const int m = 200;
    const Entries e = chain(m, skew);
    ReplicatedSparseLU lu;
    ASSERT_TRUE(lu.factor(m, e));
    std::vector<double> b(static_cast<size_t>(m));
    for (int i = 0; i < m; ++i) b[size_t(i)] = std::sin(0.37 * i) + 0.1 * i;
    const std::vector<double> expected = denseSolve(m, e, b);
    std::vector<double> y = b;
    lu.solve(y);
    for (int i = 0; i < m; ++i) EXPECT_NEAR(y[size_t(i)], expected[size_t(i)], 1e-12 * std::abs(expected[size_t(i)]) + 1e-14);
    lu.solve(b);  // a second solve with the same factors
    EXPECT_EQ(b, y);
  }
}

TEST(MpiReplicatedSparseLU, RefusesALinearlyDependentRow) {
  const int m = 50;
  Entries e = chain(m, 0.0);
  Entries dependent;
  for (const auto& x : e)
    if (x.row != 20) dependent.push_back(x);
  for (const auto& x : e)
    if (x.row == 10) dependent.push_back({20, x.col, 2.0 * x.value});  // row 20 = 2 row 10
  ReplicatedSparseLU lu;
  EXPECT_FALSE(lu.factor(m, dependent));
  Entries empty;  // a row with no entry
  for (const auto& x : e)
    if (x.row != 5) empty.push_back(x);
  EXPECT_FALSE(lu.factor(m, empty));
  EXPECT_TRUE(lu.factor(m, e));  // factors again after a refusal
  EXPECT_TRUE(lu.factor(0, {}));
}

}  // namespace
}  // namespace choc
