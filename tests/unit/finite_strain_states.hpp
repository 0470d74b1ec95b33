// Deformation states for the finite-strain element tests: nodal displacements of a homogeneous
// deformation, a general deformation gradient per kinematics, rotations; and the plastic
// element's tangent check.
#pragma once
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/Vec3.hpp"
#include "fd_tangent.hpp"
#include "fem/FiniteStrainSolid.hpp"
#include "fem/Kinematics.hpp"
#include "materials/Tensor2.hpp"
#include "test_fem_solid_cases.hpp"

namespace choc::test {

inline int componentsOf(const ElementCase& c) { return c.kinematics == Kinematics::ThreeD ? 3 : 2; }

// u_a = (F - I) (X_a - origin) on the components the kinematics carries.
inline std::vector<double> displacementOf(const ElementCase& c, const Mat3& F, const Point3& origin = {0, 0, 0}) {
  const int nc = componentsOf(c);
  std::vector<double> u;
  for (const Point3& X : c.x)
    for (int i = 0; i < nc; ++i) {
      double v = 0.0;
      for (int J = 0; J < 3; ++J) v += (F[i][J] - (i == J)) * (X[J] - origin[J]);
      u.push_back(v);
    }
  return u;
}

// A stretch with shear in the kinematics' plane(s), then (not axisymmetric) a rotation of
// 30 degrees about z: a general F with det F = 1.14.
inline Mat3 generalGradient(Kinematics k) {
  if (k == Kinematics::Axisymmetric) return {{{1.2, 0, 0}, {0, 0.85, 0}, {0, 0, 1.2}}};
  const Mat3 U = k == Kinematics::ThreeD ? Mat3{{{1.2, 0.15, -0.1}, {0.05, 0.9, 0.2}, {0.1, -0.05, 1.1}}}
                                         : Mat3{{{1.2, 0.15, 0}, {0.05, 0.9, 0}, {0, 0, 1}}};
  const double a = std::acos(-1.0) / 6;
  const Mat3 R = {{{std::cos(a), -std::sin(a), 0}, {std::sin(a), std::cos(a), 0}, {0, 0, 1}}};
  return choc::multiply(R, U);
}

// A rotation by angle about an axis (about z in 2D).
inline Mat3 rotation(Kinematics k, double angle) {
  Point3 n = k == Kinematics::ThreeD ? Point3{0.3, -0.5, 0.81} : Point3{0, 0, 1};
  const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  for (double& v : n) v /= len;
  const double c = std::cos(angle), s = std::sin(angle);
  Mat3 R{};
  const double K[3][3] = {{0, -n[2], n[1]}, {n[2], 0, -n[0]}, {-n[1], n[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) R[i][j] = c * (i == j) + s * K[i][j] + (1 - c) * n[i] * n[j];
  return R;
}

// A plastic element's tangent against central differences of its force (J2 with sigma_y = E / 200),
// from a yielded committed state: a first deformation (plus `wobble` times a nodal pattern, which
// makes J vary over the element), then a general state in the plastic branch. Returns the largest
// |K_ij - K_ji| over the largest |K_ij| (NaN when the first deformation did not yield: a failure).
inline double checkPlasticTangent(const FiniteStrainSolid& el, const ElementCase& c, double wobble, const std::string& label) {
  const ElementGeometry g = el.geometry(c.x);
  Mat3 F1 = identity3();
  F1[0][0] = 1.02, F1[1][1] = 0.99;
  if (c.kinematics != Kinematics::Axisymmetric) F1[0][1] = 0.015;
  std::vector<double> old(size_t(el.stateSize())), committed(size_t(el.stateSize())), f;
  el.initialState(old.data());
  std::vector<double> u1 = displacementOf(c, F1);
  for (size_t j = 0; j < u1.size(); ++j) u1[j] += wobble * std::cos(1.3 * double(j));
  double work = 0.0;
  el.evaluate(g, u1, f, nullptr, old.data(), committed.data(), &work);
  EXPECT_GT(work, 0.0) << "the first deformation must yield " << label;
  if (!(work > 0.0)) return std::nan("");
  std::vector<double> u = displacementOf(c, generalGradient(c.kinematics));
  for (size_t j = 0; j < u.size(); ++j) u[j] = 0.1 * u[j] + 0.003 * std::sin(1.7 * double(j) + 0.3);
  auto R = [&](const std::vector<double>& x) {
    std::vector<double> r;
    el.evaluate(g, x, r, nullptr, committed.data());
    return r;
  };
  DenseMatrix K;
  el.evaluate(g, u, f, &K, committed.data());
  test::Dense J(K.rows(), K.cols());
  double asym = 0.0, norm = 0.0;
  for (int i = 0; i < K.rows(); ++i)
    for (int j = 0; j < K.cols(); ++j) {
      J(i, j) = K(i, j);
      asym = std::max(asym, std::abs(K(i, j) - K(j, i))), norm = std::max(norm, std::abs(K(i, j)));
    }
  test::TangentCheckOptions o;
  o.scale = 1e-3;  // the strain over which the plastic response varies (yield strain 5e-3)
  EXPECT_TRUE(test::tangentMatches(R, J, u, o)) << label;
  EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), u, o)) << label;
  return asym / norm;
}

// An element's force against central differences of the energy evaluate returns, at u (the
// element's reference geometry from c), and a perturbed force failing the same check.
inline void expectForceIsTheEnergysDerivative(const FiniteStrainSolid& el, const ElementCase& c,
                                              const std::vector<double>& u, double scale = 0.1) {
  auto W = [&](const std::vector<double>& x) {
    std::vector<double> f;
    return std::vector<double>{el.evaluate(c.x, x, f, nullptr)};
  };
  std::vector<double> f;
  el.evaluate(c.x, u, f, nullptr);
  Dense J(1, int(f.size()));
  for (size_t k = 0; k < f.size(); ++k) J(0, int(k)) = f[k];
  TangentCheckOptions o;
  o.scale = scale;
  EXPECT_TRUE(tangentMatches(W, J, u, o));
  EXPECT_TRUE(tangentMismatches(W, perturbed(J), u, o));
}

// An element's tangent K (evaluate's) against central differences of its force at u, and a
// perturbed K failing the same check.
inline void expectTangentMatchesTheForce(const FiniteStrainSolid& el, const ElementGeometry& g,
                                         const std::vector<double>& u, double scale = 0.1) {
  auto R = [&](const std::vector<double>& x) {
    std::vector<double> r;
    el.evaluate(g, x, r, nullptr);
    return r;
  };
  std::vector<double> f;
  DenseMatrix K;
  el.evaluate(g, u, f, &K);
  Dense J(K.rows(), K.cols());
  for (int i = 0; i < K.rows(); ++i)
    for (int j = 0; j < K.cols(); ++j) J(i, j) = K(i, j);
  TangentCheckOptions o;
  o.scale = scale;
  EXPECT_TRUE(tangentMatches(R, J, u, o));
  EXPECT_TRUE(tangentMismatches(R, perturbed(J), u, o));
}

}  // namespace choc::test
