#include "contact/ForwardIncrementSolver.hpp"

#include <algorithm>
#include <cmath>

namespace choc {

namespace {

// A constraint's part on one rigid body: F = sum c e_k, T = sum c r_k x e_k over its terms on
// the body's DOFs, with the motion a unit pressure gives it over h2: dV = h2 F / m, dW = h2 I^-1 T.
struct BodyTerm {
  int body;
  Vec3 F, T, dV, dW;
};

Vec3 times(const std::array<double, 9>& A, const Vec3& x) {
  return {A[0] * x[0] + A[1] * x[1] + A[2] * x[2], A[3] * x[0] + A[4] * x[1] + A[5] * x[2],
          A[6] * x[0] + A[7] * x[1] + A[8] * x[2]};
}

std::vector<BodyTerm> bodyTermsOf(const std::vector<std::pair<int, double>>& terms, const RigidContactBodies& rigid,
                                  double h2) {
  std::vector<BodyTerm> out;
  for (const auto& [k, c] : terms) {
    const RigidContactDof& d = rigid.dofs[size_t(k)];
    if (d.body < 0) continue;
    auto it = std::find_if(out.begin(), out.end(), [&](const BodyTerm& t) { return t.body == d.body; });
    if (it == out.end()) it = out.insert(out.end(), BodyTerm{d.body, {}, {}, {}, {}});
    Vec3 e{};
    e[size_t(d.component)] = c;
    it->F[size_t(d.component)] += c;
    const Vec3 m = cross(d.lever, e);
    for (int i = 0; i < 3; ++i) it->T[size_t(i)] += m[size_t(i)];
  }
  for (BodyTerm& t : out) {
    const Vec3& w = rigid.inverseMass[size_t(t.body)];
    t.dV = {h2 * w[0] * t.F[0], h2 * w[1] * t.F[1], h2 * w[2] * t.F[2]};
    const Vec3 a = times(rigid.inverseInertia[size_t(t.body)], t.T);
    t.dW = {h2 * a[0], h2 * a[1], h2 * a[2]};
  }
  return out;
}

}  // namespace

ForwardIncrementResult solveForwardIncrement(const std::vector<std::vector<std::pair<int, double>>>& terms,
                                             const std::vector<double>& gaps,
                                             const std::vector<double>& inverseMass, double h2,
                                             int maxSweeps, bool unilateral, const RigidContactBodies* rigid) {
  const std::vector<double>& w = inverseMass;
  const size_t nS = terms.size();
  ForwardIncrementResult out;
  std::vector<double>& lam = out.lambda;
  lam.assign(nS, 0.0);
  std::vector<double> diag(nS, 0.0), shift(w.size(), 0.0);
  std::vector<std::vector<BodyTerm>> bodyTerms(rigid ? nS : 0);
  std::vector<Vec3> bodyShift(rigid ? 2 * rigid->inverseMass.size() : 0, Vec3{});  // per body: dV, dW
  double scale = 0.0;
  for (size_t s = 0; s < nS; ++s) {
    for (const auto& [k, c] : terms[s]) diag[s] += h2 * c * c * w[k];
    if (rigid) {
      bodyTerms[s] = bodyTermsOf(terms[s], *rigid, h2);
      for (const BodyTerm& t : bodyTerms[s]) diag[s] += dot(t.F, t.dV) + dot(t.T, t.dW);
    }
    scale = std::max(scale, std::abs(gaps[s]));
  }
  const double tol = 1e-12 * scale;
  for (; out.sweeps < maxSweeps; ++out.sweeps) {
    double change = 0.0;  // largest change of a gap in this sweep [m]
    for (size_t s = 0; s < nS; ++s) {
      if (!(diag[s] > 0)) continue;
      double r = gaps[s];
      for (const auto& [k, c] : terms[s]) r += c * shift[k];
      if (rigid)
        for (const BodyTerm& t : bodyTerms[s])
          r += dot(t.F, bodyShift[2 * size_t(t.body)]) + dot(t.T, bodyShift[2 * size_t(t.body) + 1]);
      const double next = unilateral ? std::max(0.0, lam[s] - r / diag[s]) : lam[s] - r / diag[s];
      const double d = next - lam[s];
      if (d == 0.0) continue;
      for (const auto& [k, c] : terms[s]) shift[k] += h2 * w[k] * c * d;
      if (rigid)
        for (const BodyTerm& t : bodyTerms[s])
          for (int i = 0; i < 3; ++i) {
            bodyShift[2 * size_t(t.body)][size_t(i)] += t.dV[size_t(i)] * d;
            bodyShift[2 * size_t(t.body) + 1][size_t(i)] += t.dW[size_t(i)] * d;
          }
      lam[s] = next;
      change = std::max(change, std::abs(d) * diag[s]);
    }
    if (change <= tol) {
      out.converged = true;
      break;
    }
  }
  return out;
}

}  // namespace choc
