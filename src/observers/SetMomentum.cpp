#include "observers/SetMomentum.hpp"

#include <Tpetra_Vector.hpp>

namespace choc {

std::array<RCP<Vector>, 3> setIndicators(const Probe& p, RCP<const Map> map) {
  std::array<RCP<Vector>, 3> e;
  for (int c = 0; c < 3; ++c) {
    e[size_t(c)] = rcp(new Vector(map));
    auto d = e[size_t(c)]->getDataNonConst();
    for (const auto& dofs : p.dofs) {
      if (dofs[size_t(c)] < 0) continue;
      const LO l = map->getLocalElement(GO(dofs[size_t(c)]));
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) d[l] = 1.0;
    }
  }
  return e;
}

// s: P[3], mass[3], first moments[3], then A[a][b] = sum x_a (M v)_b (9).
std::array<double, 18> localMomentumSums(const Probe& p, const Vector& u, const Vector& Mv,
                                         const std::array<RCP<Vector>, 3>& w) {
  std::array<double, 18> s{};
  auto map = u.getMap();
  auto ud = u.getData(), pd = Mv.getData();
  std::array<Teuchos::ArrayRCP<const double>, 3> wd = {w[0]->getData(), w[1]->getData(), w[2]->getData()};
  for (size_t i = 0; i < p.dofs.size(); ++i) {
    std::array<LO, 3> l{};
    bool owned = false;
    for (int c = 0; c < 3; ++c) {
      const long long d = p.dofs[i][size_t(c)];
      l[size_t(c)] = d < 0 ? LO(-1) : map->getLocalElement(GO(d));
      if (l[size_t(c)] == Teuchos::OrdinalTraits<LO>::invalid()) l[size_t(c)] = -1;
      owned = owned || l[size_t(c)] >= 0;
    }
    if (!owned) continue;  // a node's DOFs live on its owner rank
    std::array<double, 3> x{}, mv{};
    for (int c = 0; c < 3; ++c) {
      const LO lc = l[size_t(c)];
      x[size_t(c)] = p.X[i][c] + (lc >= 0 ? ud[lc] : 0.0);
      mv[size_t(c)] = lc >= 0 ? pd[lc] : 0.0;
      const double m = lc >= 0 ? wd[size_t(c)][lc] : 0.0;
      s[size_t(c)] += mv[size_t(c)];
      s[size_t(3 + c)] += m;
      s[size_t(6 + c)] += m * x[size_t(c)];
    }
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) s[size_t(9 + 3 * a + b)] += x[size_t(a)] * mv[size_t(b)];
  }
  return s;
}

std::array<double, 6> momentumFromSums(const std::array<double, 18>& s) {
  std::array<double, 3> P = {s[0], s[1], s[2]}, c{};
  for (int k = 0; k < 3; ++k) c[size_t(k)] = s[size_t(3 + k)] > 0 ? s[size_t(6 + k)] / s[size_t(3 + k)] : 0.0;
  auto A = [&](int a, int b) { return s[size_t(9 + 3 * a + b)]; };
  // About the origin, L_a = A(b, c) - A(c, b) for (a, b, c) cyclic; about c: minus c x P.
  std::array<double, 6> r{};
  for (int a = 0; a < 3; ++a) {
    const int b = (a + 1) % 3, d = (a + 2) % 3;
    r[size_t(a)] = P[size_t(a)];
    r[size_t(3 + a)] = A(b, d) - A(d, b) - (c[size_t(b)] * P[size_t(d)] - c[size_t(d)] * P[size_t(b)]);
  }
  return r;
}

}  // namespace choc
