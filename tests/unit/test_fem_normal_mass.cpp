// 'Contact Mass' = normal (fem/NormalMassRemoval.hpp): the contact nodes lose their mass along
// their normals only. On one HEX8 element with its face z = 0 on a contact surface, M' = T^T M T:
//   - M' d_k = 0 for every contact node k and its normal d_k (no inertia along it);
//   - 1_c^T M' 1_c = 1_c^T M 1_c for every component (T 1 = 1), to the rounding of summing the
//     n^2 entries (Higham, gamma_{n^2}, as in test_fem_mass_redistribution.cpp);
//   - the contact nodes keep their tangential mass (the lumped one exactly);
//   - with every direction of a node listed, the redistribution of Khenous et al.;
//   - turned with the element (frame invariance): M'(R x, R d) = R_b M'(x, d) R_b^T.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "fem/Assembler.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/NormalMassRemoval.hpp"
#include "test_fem_helpers.hpp"

using namespace choc;
using namespace choc::test;

namespace {

const Material kSteel{2e11, 0.3, 7800.0};
const double kU = std::numeric_limits<double>::epsilon() / 2;
const double kN2u = 24.0 * 24.0 * kU / (1 - 24.0 * 24.0 * kU);
const std::vector<int> kXYZ = {0, 1, 2};

std::vector<Point3> brick(double a, double b, double h) {
  return {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, h}, {a, 0, h}, {a, b, h}, {0, b, h}};
}

// The normal mass of the element with `dirs` on nodes 0..3 (none on 4..7).
DenseMatrix normalMass(const std::vector<Point3>& x, const std::vector<std::vector<Point3>>& dirs, MassKind kind) {
  DenseMatrix M;
  makeHex8(kSteel)->mass(x, kind, M);
  std::vector<const std::vector<Point3>*> d;
  for (const auto& v : dirs) d.push_back(&v);
  removeNormalMass(x, d, kXYZ, kind, M);
  return M;
}

std::vector<std::vector<Point3>> bottom(const std::vector<Point3>& n) {
  std::vector<std::vector<Point3>> d(8);
  for (int k = 0; k < 4; ++k) d[size_t(k)] = n;
  return d;
}

double absSum(const DenseMatrix& M) {
  double s = 0;
  for (int i = 0; i < M.rows(); ++i)
    for (int j = 0; j < M.cols(); ++j) s += std::fabs(M(i, j));
  return s;
}

// Per component c, 1_c^T M 1_c.
double translationMass(const DenseMatrix& M, int c) {
  double s = 0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) s += M(i * 3 + c, j * 3 + c);
  return s;
}

void checkElement(MassKind kind) {
  const double a = 0.02, b = 0.03, h = 0.025;
  const auto x = brick(a, b, h);
  DenseMatrix M0;
  makeHex8(kSteel)->mass(x, kind, M0);
  const DenseMatrix M1 = normalMass(x, bottom({{0, 0, 1}}), kind);
  const double tol = kN2u * (absSum(M0) + absSum(M1));
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(translationMass(M1, c), translationMass(M0, c), tol) << "component " << c;
  // No inertia along the normal: the z row and column of nodes 0..3 vanish.
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 24; ++j) {
      EXPECT_NEAR(M1(k * 3 + 2, j), 0.0, tol) << "node " << k;
      EXPECT_NEAR(M1(j, k * 3 + 2), 0.0, tol) << "node " << k;
    }
  // Along the surface the contact nodes keep their mass: the x and y blocks are M0's.
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j)
      if (i % 3 != 2 && j % 3 != 2) EXPECT_NEAR(M1(i, j), M0(i, j), tol) << i << ", " << j;
  EXPECT_LE(asymmetry(M1), tol);
  EXPECT_GE(symmetricEigenvalues(M1).front(), -24 * kU * maxAbs(M1) * 24);
  if (kind == MassKind::Lumped)
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < 24; ++j)
        if (i != j) EXPECT_EQ(M1(i, j), 0.0) << "a lumped matrix with axis normals stays diagonal";
}

// R: the rotation by `angle` about the unit axis (Rodrigues).
std::array<Point3, 3> rotation(double angle, Point3 axis) {
  const double c = std::cos(angle), s = std::sin(angle), n = norm(axis);
  for (double& v : axis) v /= n;
  std::array<Point3, 3> R{};
  const double K[3][3] = {{0, -axis[2], axis[1]}, {axis[2], 0, -axis[0]}, {-axis[1], axis[0], 0}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double k2 = 0;
      for (int l = 0; l < 3; ++l) k2 += K[i][l] * K[l][j];
      R[i][j] = (i == j ? 1.0 : 0.0) + s * K[i][j] + (1 - c) * k2;
    }
  return R;
}

Point3 apply(const std::array<Point3, 3>& R, const Point3& v) {
  Point3 out{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) out[i] += R[i][j] * v[j];
  return out;
}

void checkFrame(MassKind kind) {
  const auto x = brick(0.02, 0.03, 0.025);
  const auto R = rotation(0.7, {1, 2, 3});
  std::vector<Point3> xr;
  for (const auto& p : x) xr.push_back(apply(R, p));
  const DenseMatrix M1 = normalMass(x, bottom({{0, 0, 1}}), kind);
  const DenseMatrix Mr = normalMass(xr, bottom({apply(R, {0, 0, 1})}), kind);
  // Both sides are sums of the n^2 = 576 products of T^T M T (the turned one also of R's 9 per
  // entry): Higham's gamma_{n^2}, about 600 u of the largest entry, rounded up to 1e3 u.
  const double tol = 1e3 * kU * maxAbs(M1);
  for (int a = 0; a < 8; ++a)
    for (int b = 0; b < 8; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double e = 0;  // (R M1_ab R^T)_ij
          for (int k = 0; k < 3; ++k)
            for (int l = 0; l < 3; ++l) e += R[i][k] * M1(a * 3 + k, b * 3 + l) * R[j][l];
          EXPECT_NEAR(Mr(a * 3 + i, b * 3 + j), e, tol) << a << "," << b << " (" << i << ", " << j << ")";
        }
}

}  // namespace

TEST(NormalMass, ConsistentHex8KeepsElementMassAndTangentialMass) { checkElement(MassKind::Consistent); }

TEST(NormalMass, LumpedHex8KeepsElementMassAndTangentialMass) { checkElement(MassKind::Lumped); }

TEST(NormalMass, TurnsWithTheElementConsistent) { checkFrame(MassKind::Consistent); }

TEST(NormalMass, TurnsWithTheElementLumped) { checkFrame(MassKind::Lumped); }

TEST(NormalMass, EveryDirectionIsTheRedistribution) {
  const auto x = brick(0.02, 0.03, 0.025);
  for (MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
    const DenseMatrix M1 = normalMass(x, bottom({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), kind);
    DenseMatrix M2;
    makeHex8(kSteel)->mass(x, kind, M2);
    redistributeElementMass(x, {1, 1, 1, 1, 0, 0, 0, 0}, 3, kind, M2);
    const double tol = kN2u * absSum(M2);
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < 24; ++j) EXPECT_NEAR(M1(i, j), M2(i, j), tol) << i << ", " << j;
  }
}

TEST(NormalMass, AnElementWithEveryNodeOnTheSurfaceIsRefused) {
  const auto x = brick(0.02, 0.02, 0.02);
  std::vector<std::vector<Point3>> d(8, std::vector<Point3>{{0, 0, 1}});
  EXPECT_THROW(normalMass(x, d, MassKind::Consistent), std::invalid_argument);
}
