// Two-node Timoshenko beam: invariants on a generic (rotated) beam and closed-form responses.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fem/Beam2Element.hpp"
#include "fem/Components.hpp"
#include "test_fem_helpers.hpp"

using namespace choc;
using namespace choc::test;

namespace {

// A generic beam: unit axis e (0.6, -0.48, 0.64), not aligned with any global axis; an
// orientation vector that is not orthogonal to the axis; a section with Iy != Iz, ky != kz.
struct BeamCase {
  Material mat{2e11, 0.3, 7800.0};
  BeamSection sec;
  double L = 0.1;
  Point3 e = {0.6, -0.48, 0.64};
  std::vector<Point3> x;
  Point3 ey, ez;  // expected local axes, computed here independently
  BeamCase() {
    sec.area = 6e-4;
    sec.Iy = 2e-8;
    sec.Iz = 4.5e-8;
    sec.torsionConstant = 3e-8;
    sec.shearCoefficientY = 0.8;
    sec.shearCoefficientZ = 0.7;
    sec.orientation = {0.2, 0.9, -0.3};
    const Point3 x1 = {0.3, -0.2, 0.5};
    x = {x1, {x1[0] + L * e[0], x1[1] + L * e[1], x1[2] + L * e[2]}};
    const Point3& v = sec.orientation;
    const double p = dot3(v, e);
    ey = {v[0] - p * e[0], v[1] - p * e[1], v[2] - p * e[2]};
    const double n = std::sqrt(dot3(ey, ey));
    for (double& c : ey) c /= n;
    ez = cross3(e, ey);
  }
  double G() const { return mat.shearModulus(); }
};

// Clamps node 1 and solves for node 2 under a tip force f (global) and tip moment m.
void cantilever(const DenseMatrix& K, const Point3& f, const Point3& m, Point3& u, Point3& rot) {
  DenseMatrix K22(6, 6);
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) K22(i, j) = K(6 + i, 6 + j);
  const Vec d = solve(K22, {f[0], f[1], f[2], m[0], m[1], m[2]});
  u = {d[0], d[1], d[2]};
  rot = {d[3], d[4], d[5]};
}

constexpr double kTol = 1e-10;

}  // namespace

TEST(Beam2, ComponentsAndNodes) {
  BeamCase c;
  auto el = makeBeam2(c.mat, c.sec);
  EXPECT_EQ(el->numNodes(), 2);
  EXPECT_EQ(el->components(), (std::vector<int>{DX, DY, DZ, DRX, DRY, DRZ}));
}

TEST(Beam2, LocalAxes) {
  BeamCase c;
  const auto ax = beamLocalAxes(c.x[0], c.x[1], c.sec.orientation);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(ax[0][i], c.e[i], 1e-14);
    EXPECT_NEAR(ax[1][i], c.ey[i], 1e-14);
    EXPECT_NEAR(ax[2][i], c.ez[i], 1e-14);
  }
  // Defaults: global y, or global z for a beam along y.
  auto a = beamLocalAxes({0, 0, 0}, {3, 0, 0}, {0, 0, 0});
  EXPECT_EQ(a[1], (Point3{0, 1, 0}));
  EXPECT_EQ(a[2], (Point3{0, 0, 1}));
  a = beamLocalAxes({1, 1, 1}, {1, -1, 1}, {0, 0, 0});
  EXPECT_EQ(a[0], (Point3{0, -1, 0}));
  EXPECT_EQ(a[1], (Point3{0, 0, 1}));
  EXPECT_EQ(a[2], (Point3{-1, 0, 0}));
}

TEST(Beam2, RejectsParallelOrientationAndZeroLength) {
  BeamCase c;
  c.sec.orientation = {-2 * c.e[0], -2 * c.e[1], -2 * c.e[2]};
  auto el = makeBeam2(c.mat, c.sec);
  DenseMatrix K;
  try {
    el->stiffness(c.x, K);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& err) {
    EXPECT_NE(std::string(err.what()).find("parallel"), std::string::npos) << err.what();
  }
  EXPECT_THROW(el->mass(c.x, MassKind::Consistent, K), std::invalid_argument);
  BeamCase d;
  auto el2 = makeBeam2(d.mat, d.sec);
  EXPECT_THROW(el2->stiffness({d.x[0], d.x[0]}, K), std::invalid_argument);
  d.sec.area = 0.0;
  EXPECT_THROW(makeBeam2(d.mat, d.sec), std::invalid_argument);
}

TEST(Beam2, StiffnessSymmetricPsdWithSixRigidModes) {
  BeamCase c;
  DenseMatrix K;
  makeBeam2(c.mat, c.sec)->stiffness(c.x, K);
  ASSERT_EQ(K.rows(), 12);
  ASSERT_EQ(K.cols(), 12);
  const double kmax = maxAbs(K);
  EXPECT_LE(asymmetry(K), kTol * kmax);
  const Vec ev = symmetricEigenvalues(K);
  EXPECT_GE(ev.front(), -kTol * ev.back());
  int zeros = 0;
  for (double l : ev) zeros += l < kTol * ev.back();
  EXPECT_EQ(zeros, 6);
  for (const Vec& r : rigidBodyModes(c.x, 6, {1.3, 0.7, -2.1}))
    EXPECT_LE(maxAbs(multiply(K, r)), kTol * kmax * maxAbs(r) * 3.0);
}

TEST(Beam2, AxialTorsionAndTimoshenkoCantilever) {
  BeamCase c;
  DenseMatrix K;
  makeBeam2(c.mat, c.sec)->stiffness(c.x, K);
  const double E = c.mat.youngsModulus, G = c.G(), A = c.sec.area, L = c.L;
  // Axial stiffness of node 2 along the axis.
  double kax = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) kax += c.e[i] * K(6 + i, 6 + j) * c.e[j];
  EXPECT_NEAR(kax, E * A / L, kTol * E * A / L);

  const double P = 1234.0, T = 56.0;
  const Point3 zero = {0, 0, 0};
  Point3 u, rot;
  // Axial load.
  cantilever(K, {P * c.e[0], P * c.e[1], P * c.e[2]}, zero, u, rot);
  EXPECT_NEAR(dot3(u, c.e), P * L / (E * A), kTol * P * L / (E * A));
  // Torsion.
  cantilever(K, zero, {T * c.e[0], T * c.e[1], T * c.e[2]}, u, rot);
  const double twist = T * L / (G * c.sec.torsionConstant);
  EXPECT_NEAR(dot3(rot, c.e), twist, kTol * twist);
  EXPECT_NEAR(dot3(rot, c.ey), 0.0, kTol * twist);
  // Bending along local y (about local z: Iz, shear coefficient ky).
  cantilever(K, {P * c.ey[0], P * c.ey[1], P * c.ey[2]}, zero, u, rot);
  double shear = P * L / (c.sec.shearCoefficientY * G * A);
  double defl = P * L * L * L / (3 * E * c.sec.Iz) + shear;
  ASSERT_GT(shear / defl, 0.05);  // the case does exercise shear deformation
  EXPECT_NEAR(dot3(u, c.ey), defl, kTol * defl);
  EXPECT_NEAR(dot3(u, c.ez), 0.0, kTol * defl);
  EXPECT_NEAR(dot3(rot, c.ez), P * L * L / (2 * E * c.sec.Iz), kTol * P * L * L / (E * c.sec.Iz));
  // Bending along local z (about local y: Iy, shear coefficient kz); rotation about -y.
  cantilever(K, {P * c.ez[0], P * c.ez[1], P * c.ez[2]}, zero, u, rot);
  shear = P * L / (c.sec.shearCoefficientZ * G * A);
  defl = P * L * L * L / (3 * E * c.sec.Iy) + shear;
  EXPECT_NEAR(dot3(u, c.ez), defl, kTol * defl);
  EXPECT_NEAR(dot3(u, c.ey), 0.0, kTol * defl);
  EXPECT_NEAR(dot3(rot, c.ey), -P * L * L / (2 * E * c.sec.Iy), kTol * P * L * L / (E * c.sec.Iy));
}

TEST(Beam2, MassTotalsAndDefiniteness) {
  BeamCase c;
  auto el = makeBeam2(c.mat, c.sec);
  const double rho = c.mat.density, m = rho * c.sec.area * c.L;
  const double Ip = c.sec.Iy + c.sec.Iz;
  for (MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
    SCOPED_TRACE(kind == MassKind::Consistent ? "consistent" : "lumped");
    DenseMatrix M;
    el->mass(c.x, kind, M);
    ASSERT_EQ(M.rows(), 12);
    ASSERT_EQ(M.cols(), 12);
    const auto modes = rigidBodyModes(c.x, 6, c.x[0]);
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(quadratic(M, modes[d]), m, kTol * m);
    // Rigid rotation about the beam axis: torsional inertia rho Ip L.
    Vec r(12, 0.0);
    for (int n = 0; n < 2; ++n)
      for (int i = 0; i < 3; ++i) r[6 * n + 3 + i] = c.e[i];
    EXPECT_NEAR(quadratic(M, r), rho * Ip * c.L, kTol * rho * Ip * c.L);
    EXPECT_LE(asymmetry(M), kTol * maxAbs(M));
    if (kind == MassKind::Lumped) {
      for (int i = 0; i < 12; ++i) {
        EXPECT_GT(M(i, i), 0.0);
        for (int j = 0; j < 12; ++j)
          if (i != j) {
            EXPECT_EQ(M(i, j), 0.0) << i << "," << j;
          }
      }
    } else {
      const Vec ev = symmetricEigenvalues(M);
      EXPECT_GT(ev.front(), 1e-8 * ev.back());
      // Hermite cubics represent a rigid rotation about a transverse axis through the
      // midpoint exactly: u = w x (x - xm), theta = w gives rho A L^3/12 (no rotary inertia).
      const Point3 xm = {(c.x[0][0] + c.x[1][0]) / 2, (c.x[0][1] + c.x[1][1]) / 2,
                         (c.x[0][2] + c.x[1][2]) / 2};
      for (const Point3& w : {c.ey, c.ez}) {
        Vec q(12, 0.0);
        for (int n = 0; n < 2; ++n) {
          const Point3 u = cross3(w, {c.x[n][0] - xm[0], c.x[n][1] - xm[1], c.x[n][2] - xm[2]});
          for (int i = 0; i < 3; ++i) {
            q[6 * n + i] = u[i];
            q[6 * n + 3 + i] = w[i];
          }
        }
        const double I = m * c.L * c.L / 12;
        EXPECT_NEAR(quadratic(M, q), I, kTol * I);
      }
    }
  }
}
