// J2 plasticity at one point, for the material tests: the consistent tangent against central
// differences of the return map, and uniaxial stress by a bisection on the lateral stretch.
#pragma once
#include <array>
#include <vector>

#include <gtest/gtest.h>

#include "fd_tangent.hpp"
#include "materials/J2Plasticity.hpp"

namespace choc {
namespace test {

inline Mat3 matrixOf(const std::vector<double>& f) {
  Mat3 F{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) F[i][j] = f[size_t(3 * i + j)];
  return F;
}

inline std::vector<double> entries(const Mat3& F) {
  std::vector<double> f;
  for (const auto& row : F) f.insert(f.end(), row.begin(), row.end());
  return f;
}

inline ::testing::AssertionResult tangentAt(const J2Plasticity& m, const Mat3& F, const double* state, bool expectYield,
                                     double dt = 0.0) {
  J2Response r;
  m.respond(F, state, true, r, false, dt);
  if (r.yielded != expectYield) return ::testing::AssertionFailure() << "yielded = " << r.yielded;
  auto P = [&](const std::vector<double>& f) {
    J2Response q;
    m.respond(matrixOf(f), state, false, q, false, dt);
    return entries(q.P);
  };
  Dense A(9, 9);
  for (int a = 0; a < 9; ++a)
    for (int b = 0; b < 9; ++b) A(a, b) = r.A[a][b];
  TangentCheckOptions o;
  o.scale = 1e-3;  // the strain over which the response varies near yield (sigma_y / E = 3.4e-3)
  const auto x = entries(F);
  auto ok = tangentMatches(P, A, x, o);
  if (!ok) return ok;
  return tangentMismatches(P, perturbed(A), x, o);
}

// Uniaxial stress, F = diag(l, t, t) with t such that the lateral stress is zero (bisection).
// Small strain: sigma = E eps below yield, sigma = (sigma_y + H eps) / (1 + H / E) above.
// Finite strain: the same in the Kirchhoff stress tau = P_11 l and the logarithmic strain ln l
// (Hencky elasticity and the exponential map: exact on a proportional path).
struct Uniaxial {
  double axial, alpha;
};

inline Uniaxial uniaxial(const J2Plasticity& m, double l, const double* state, std::array<double, kJ2StateSize>* next,
                         double dt = 0.0) {
  auto lateral = [&](double t, J2Response& r) {
    m.respond({{{l, 0, 0}, {0, t, 0}, {0, 0, t}}}, state, false, r, false, dt);
    return r.P[1][1];
  };
  J2Response r;
  double lo = 0.5, hi = 1.5;  // lateral stress rises with t
  for (int k = 0; k < 200; ++k) (lateral(0.5 * (lo + hi), r) > 0 ? hi : lo) = 0.5 * (lo + hi);
  lateral(0.5 * (lo + hi), r);
  if (next) *next = r.state;
  return {m.finiteStrain() ? r.P[0][0] * l : r.P[0][0], r.state[kJ2Alpha]};
}

}  // namespace test
}  // namespace choc
