#include "fem/ElementFrequencyBound.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_LAPACK.hpp>

#include "fem/Assembler.hpp"

namespace choc {

namespace {

// Whether M couples two active rows (the bound then does not apply).
bool couplesActiveRows(const DenseMatrix& M, const std::vector<char>& active) {
  for (int i = 0; i < M.rows(); ++i)
    for (int j = 0; j < M.cols(); ++j)
      if (i != j && active[size_t(i)] && active[size_t(j)] && M(i, j) != 0.0) return true;
  return false;
}

// M^-1/2 K M^-1/2 on the active rows that carry stiffness, M diagonal (`mass`), into the upper
// triangle of A (n x n, column-major: what LAPACK and the tests below read). Returns +inf or 0
// as elementEigenvalue documents those cases, or -1 when A holds the matrix.
double scaledStiffness(const DenseMatrix& K, const double* mass, const std::vector<char>& active,
                       std::vector<int>& keep, std::vector<double>& scale, std::vector<double>& A, int& n) {
  const int size = K.rows();
  const double* k = K.data();
  // Rows without stiffness (a rotation an element does not resist) carry no frequency.
  keep.clear();
  scale.clear();
  for (int i = 0; i < size; ++i) {
    if (!active[size_t(i)]) continue;
    bool stiff = false;
    for (int j = 0; j < size && !stiff; ++j) stiff = active[size_t(j)] && k[size_t(i) * size + j] != 0.0;
    if (!stiff) continue;
    if (!(mass[i] > 0.0)) return std::numeric_limits<double>::infinity();
    keep.push_back(i);
    scale.push_back(1.0 / std::sqrt(mass[i]));
  }
  n = static_cast<int>(keep.size());
  if (n == 0) return 0.0;
  A.resize(size_t(n) * n);
  for (int b = 0; b < n; ++b)
    for (int a = 0; a <= b; ++a) A[size_t(b) * n + a] = k[size_t(keep[a]) * size + keep[b]] * scale[a] * scale[b];
  return -1.0;
}

// The largest eigenvalue of A (n x n, column-major, upper triangle) by LAPACK DSYEV; A is overwritten.
double largestEigenvalue(std::vector<double>& A, int n) {
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  std::vector<double> w(static_cast<size_t>(n)), work(static_cast<size_t>(std::max(1, 3 * n)));
  lapack.SYEV('N', 'U', n, A.data(), n, w.data(), work.data(), int(work.size()), &info);
  if (info != 0)
    throw std::runtime_error("element eigenvalue bound: LAPACK DSYEV failed with info = " +
                             std::to_string(info));
  return w[size_t(n) - 1];
}

}  // namespace

double elementEigenvalue(const DenseMatrix& K, const DenseMatrix& M, const std::vector<char>& active) {
  if (couplesActiveRows(M, active)) return std::numeric_limits<double>::infinity();
  std::vector<int> keep;
  std::vector<double> scale, A, mass(size_t(M.rows()));
  for (int i = 0; i < M.rows(); ++i) mass[size_t(i)] = M(i, i);
  int n = 0;
  const double early = scaledStiffness(K, mass.data(), active, keep, scale, A, n);
  return early >= 0.0 ? early : largestEigenvalue(A, n);
}

bool gershgorinBelow(const double* A, int n, double mu, double& bound) {
  const double eps = std::numeric_limits<double>::epsilon();
  bound = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    double off = 0.0;
    for (int j = 0; j < i; ++j) off += std::abs(A[size_t(i) * n + j]);
    for (int j = i + 1; j < n; ++j) off += std::abs(A[size_t(j) * n + i]);
    const double diagonal = A[size_t(i) * n + i];
    // the row's sum and its rounding: at most (n + 1) eps / 2 of the sum of its magnitudes
    bound = std::max(bound, diagonal + off + (n + 1) * eps * (std::abs(diagonal) + off));
  }
  return bound <= mu;
}

bool choleskyBelow(const double* A, int n, double mu, std::vector<double>& R, double& bound) {
  // Right-looking: each pivot's row scaled, then the trailing upper triangle updated by its outer
  // product (independent updates along contiguous columns).
  R.resize(size_t(n) * (n + 1));
  double* B = R.data();
  double* row = B + size_t(n) * n;
  double trace = 0.0;
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < j; ++i) B[size_t(j) * n + i] = -A[size_t(j) * n + i];
    B[size_t(j) * n + j] = mu - A[size_t(j) * n + j];
    trace += B[size_t(j) * n + j];
  }
  for (int k = 0; k < n; ++k) {
    const double d = B[size_t(k) * n + k];
    if (!(d > 0.0)) return false;
    const double inverse = 1.0 / std::sqrt(d);
    for (int j = k + 1; j < n; ++j) row[j] = B[size_t(j) * n + k] * inverse;
    for (int j = k + 1; j < n; ++j) {
      double* bj = B + size_t(j) * n;
      const double rj = row[j];
      for (int i = k + 1; i <= j; ++i) bj[i] -= row[i] * rj;
    }
  }
  bound = mu + (n + 1) * std::numeric_limits<double>::epsilon() * trace;
  return true;
}

void ElementEigenvalueMaximum::add(const DenseMatrix& K, const std::vector<double>& mass,
                                   const std::vector<char>& active) {
  ++elements_;
  if (std::isinf(largest_)) return;
  int n = 0;
  const double early = scaledStiffness(K, mass.data(), active, keep_, scale_, A_, n);
  if (early >= 0.0) {
    largest_ = std::max(largest_, early);
    return;
  }
  const double mu = largest_ * (1.0 + kTieMargin);
  double bound = 0.0;
  if (largest_ > 0.0 && (gershgorinBelow(A_.data(), n, mu, bound) || choleskyBelow(A_.data(), n, mu, R_, bound))) {
    below_ = std::max(below_, bound);
    return;
  }
  ++solved_;
  largest_ = std::max(largest_, largestEigenvalue(A_, n));
}

double Assembler::eigenvalueBound(const std::vector<NodalSpring>& springs) const {
  const double inf = std::numeric_limits<double>::infinity();
  double elements = 0.0;
  std::map<long long, double> nodalMass;  // lumped masses of the springs' owned DOFs
  for (const NodalSpring& sp : springs)
    if (dofs_.ownsNode(sp.node))
      for (int c = 0; c < 3; ++c)
        if (dofs_.dof(sp.node, c) >= 0) nodalMass[dofs_.dof(sp.node, c)] = 0.0;
  std::vector<char> active;
  DenseMatrix Ke, Me;
  forEachElement([&](const LocalElement& el) {
    if (el.physics->rigid) return;  // no stiffness: no frequency (its body moves as a whole)
    if (el.physics->mass != MassKind::Lumped) {
      elements = inf;
      return;
    }
    active.resize(el.gdof.size());
    for (size_t i = 0; i < el.gdof.size(); ++i) active[i] = el.gdof[i] >= 0;
    el.physics->kernel->stiffness(el.x, Ke);
    el.physics->kernel->mass(el.x, MassKind::Lumped, Me);
    elements = std::max(elements, elementEigenvalue(Ke, Me, active));
    for (size_t i = 0; i < el.gdof.size(); ++i) {
      auto it = nodalMass.find(el.gdof[i]);
      if (it != nodalMass.end()) it->second += Me(int(i), int(i));
    }
  });
  // Gershgorin on the springs alone: row i of sum_s k_s d d^T scaled by the lumped masses.
  std::map<long long, double> rows;
  for (const NodalSpring& sp : springs) {
    if (!dofs_.ownsNode(sp.node)) continue;
    for (int i = 0; i < 3; ++i) {
      const long long gi = dofs_.dof(sp.node, i);
      if (gi < 0 || sp.direction[i] == 0.0) continue;
      double s = 0.0;
      for (int j = 0; j < 3; ++j) {
        const long long gj = dofs_.dof(sp.node, j);
        if (gj >= 0) s += std::abs(sp.direction[j]) / std::sqrt(nodalMass[gj]);
      }
      rows[gi] += sp.stiffness * std::abs(sp.direction[i]) / std::sqrt(nodalMass[gi]) * s;
    }
  }
  double springRows = 0.0;
  for (const auto& [dof, r] : rows) springRows = std::max(springRows, std::isfinite(r) ? r : inf);
  double mine[2] = {elements, springRows}, all[2] = {0.0, 0.0};
  Teuchos::reduceAll<int, double>(*comm_, Teuchos::REDUCE_MAX, 2, mine, all);
  return all[0] + all[1];
}

}  // namespace choc
