#include "solvers/SolverChoice.hpp"

#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "core/Format.hpp"
#include "fem/MatrixOps.hpp"

namespace choc {

namespace {

// sum_j |A_ij| of each local row.
std::vector<double> absoluteRowSums(const CrsMatrix& A) {
  auto rowMap = A.getRowMap();
  std::vector<double> sums(rowMap->getNodeNumElements(), 0.0);
  RowCopy row;
  for (size_t i = 0; i < sums.size(); ++i) {
    row.read(A, rowMap->getGlobalElement(LO(i)));
    for (size_t k = 0; k < row.size; ++k) sums[i] += std::abs(row.vals[k]);
  }
  return sums;
}

std::string withCommas(long long n) {
  std::string s = std::to_string(n);
  for (int i = int(s.size()) - 3; i > 0; i -= 3) s.insert(size_t(i), ",");
  return s;
}

}  // namespace

SolverChoice chooseLinearSolver(const SolverRegime& r) {
  // Direct, with the distributed package when the build has one (above kAlwaysDirectUpTo).
  const auto direct = [&r](const std::string& why) -> SolverChoice {
    if (r.distributedDirect.empty()) return {"Direct", "", "", why};
    return {"Direct", "", r.distributedDirect, why + "; " + r.distributedDirect + " factors it on every rank"};
  };
  const std::string size = withCommas(r.unknowns) + " unknowns";
  if (r.unknowns <= r.alwaysDirectUpTo())
    return {"Direct", "", "", size + ", at most " + withCommas(r.alwaysDirectUpTo()) +
                                  (r.tangentChanges ? " (a new tangent at each Newton iteration)" : "")};
  if (!r.symmetricPositive()) {
    const std::string why = size + "; the matrix is not symmetric positive definite (" + r.notSymmetricBecause + ")";
    if (r.nearlySymmetric && r.stiffnessToMass <= kJacobiUpTo)
      return {"GMRES", "Jacobi", "",
              why + ", mass-dominated: stiffness/mass " + format("%.3g", r.stiffnessToMass) + " <= " +
                  std::to_string(int(kJacobiUpTo))};
    return direct(why);
  }
  const std::string theta = format("%.3g", r.stiffnessToMass);
  const std::string limit = std::to_string(int(kJacobiUpTo));
  if (r.stiffnessToMass <= kJacobiUpTo)
    return {"CG", "Jacobi", "", size + ", symmetric, mass-dominated: stiffness/mass " + theta + " <= " + limit};
  const std::string stiff = size + ", symmetric, stiffness-dominated: stiffness/mass " + theta + " > " + limit;
  if (r.unknowns <= kDirectUpTo) return direct(stiff + ", at most " + withCommas(kDirectUpTo) + " unknowns");
  const std::string large = stiff + ", more than " + withCommas(kDirectUpTo) + " unknowns, stiffness/mass ";
  const std::string largeLimit = withCommas((long long)kLargeJacobiUpTo);
  if (r.stiffnessToMass <= kLargeJacobiUpTo) return {"CG", "Jacobi", "", large + "<= " + largeLimit};
  if (r.nodeBlocks) return {"CG", "Multigrid", "", large + "> " + largeLimit};
  return {"CG", "Additive Schwarz", "", large + "> " + largeLimit + " (no node blocks for multigrid)"};
}

double stiffnessToMassRatio(const CrsMatrix& K, const CrsMatrix& M, double mCoef, double kCoef) {
  const std::vector<double> k = absoluteRowSums(K), m = absoluteRowSums(M);
  double mine = 0.0;
  for (size_t i = 0; i < k.size() && i < m.size(); ++i) {
    if (k[i] == 0.0) continue;
    const double mass = mCoef * m[i];
    mine = std::max(mine, mass > 0 ? kCoef * k[i] / mass : std::numeric_limits<double>::infinity());
  }
  double all = 0.0;
  Teuchos::reduceAll<int, double>(*K.getRowMap()->getComm(), Teuchos::REDUCE_MAX, mine, Teuchos::outArg(all));
  return all;
}

}  // namespace choc
