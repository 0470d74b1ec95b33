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

double elementEigenvalue(const DenseMatrix& K, const DenseMatrix& M, const std::vector<char>& active) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<int> rows;
  for (int i = 0; i < K.rows(); ++i)
    if (active[i]) rows.push_back(i);
  for (int i : rows)
    for (int j : rows)
      if (i != j && M(i, j) != 0.0) return inf;
  // Rows without stiffness (a rotation an element does not resist) carry no frequency.
  std::vector<int> keep;
  std::vector<double> scale;
  for (int i : rows) {
    bool stiff = false;
    for (int j : rows) stiff = stiff || K(i, j) != 0.0;
    if (!stiff) continue;
    if (!(M(i, i) > 0.0)) return inf;
    keep.push_back(i);
    scale.push_back(1.0 / std::sqrt(M(i, i)));
  }
  const int n = static_cast<int>(keep.size());
  if (n == 0) return 0.0;
  // M^-1/2 K M^-1/2, column-major (symmetric); its largest eigenvalue by LAPACK DSYEV.
  std::vector<double> A(size_t(n) * n), w(n);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b) A[size_t(b) * n + a] = K(keep[a], keep[b]) * scale[a] * scale[b];
  Teuchos::LAPACK<int, double> lapack;
  int info = 0;
  std::vector<double> work(std::max(1, 3 * n));
  lapack.SYEV('N', 'U', n, A.data(), n, w.data(), work.data(), int(work.size()), &info);
  if (info != 0)
    throw std::runtime_error("element eigenvalue bound: LAPACK DSYEV failed with info = " +
                             std::to_string(info));
  return w[n - 1];
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
