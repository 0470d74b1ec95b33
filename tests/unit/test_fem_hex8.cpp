// Eight-node hexahedron: invariants on a distorted rotated element, patch test, oedometric
// response, mass totals and inverted-element detection.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "test_fem_helpers.hpp"

using namespace choc;
using namespace choc::test;

namespace {

constexpr double kTol = 1e-10;
const Material kSteel{2e11, 0.3, 7800.0};

// A distorted hexahedron of known volume: the prism over [0,sx]x[0,sy] whose top corners sit
// at heights h (so its top face is a non-planar bilinear patch and the map is not affine),
// then mapped by x -> R S x + t with S upper triangular. Its volume is
// det(S) * sx * sy * mean(h), since the height is bilinear over the base.
struct DistortedHex {
  std::vector<Point3> x;
  double volume = 0.0;
  DistortedHex() {
    const double sx = 0.9, sy = 1.2;
    const double h[4] = {1.0, 1.3, 0.8, 1.15};
    const double base[4][2] = {{0, 0}, {sx, 0}, {sx, sy}, {0, sy}};
    std::vector<Point3> prism;
    for (int a = 0; a < 4; ++a) prism.push_back({base[a][0], base[a][1], 0.0});
    for (int a = 0; a < 4; ++a) prism.push_back({base[a][0], base[a][1], h[a]});
    const double S[3][3] = {{1.1, 0.2, 0.1}, {0.0, 0.9, -0.15}, {0.0, 0.0, 1.05}};
    const auto R = someRotation();
    const Point3 t = {0.4, -1.1, 2.3};
    for (const Point3& p : prism) {
      Point3 q;
      for (int i = 0; i < 3; ++i) q[i] = S[i][0] * p[0] + S[i][1] * p[1] + S[i][2] * p[2];
      q = rotate(R, q);
      x.push_back({q[0] + t[0], q[1] + t[1], q[2] + t[2]});
    }
    volume = 1.1 * 0.9 * 1.05 * sx * sy * (h[0] + h[1] + h[2] + h[3]) / 4;
  }
};

// Stress from a displacement gradient du_i/dx_j (isotropic, Voigt-free 3x3).
std::array<Point3, 3> stress(const Material& m, const std::array<Point3, 3>& grad) {
  const double nu = m.poissonsRatio, E = m.youngsModulus;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double tr = grad[0][0] + grad[1][1] + grad[2][2];
  std::array<Point3, 3> s;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s[i][j] = mu * (grad[i][j] + grad[j][i]) + (i == j) * lambda * tr;
  return s;
}

}  // namespace

TEST(Hex8, ComponentsAndNodes) {
  auto el = makeHex8(kSteel);
  EXPECT_EQ(el->numNodes(), 8);
  EXPECT_EQ(el->components(), (std::vector<int>{DX, DY, DZ}));
}

TEST(Hex8, StiffnessSymmetricPsdWithSixRigidModes) {
  DistortedHex hex;
  DenseMatrix K;
  makeHex8(kSteel)->stiffness(hex.x, K);
  ASSERT_EQ(K.rows(), 24);
  ASSERT_EQ(K.cols(), 24);
  const double kmax = maxAbs(K);
  EXPECT_LE(asymmetry(K), kTol * kmax);
  const Vec ev = symmetricEigenvalues(K);
  EXPECT_GE(ev.front(), -kTol * ev.back());
  int zeros = 0;
  for (double l : ev) zeros += l < kTol * ev.back();
  EXPECT_EQ(zeros, 6);
  for (const Vec& r : rigidBodyModes(hex.x, 3, {-0.7, 1.9, 0.35}))
    EXPECT_LE(maxAbs(multiply(K, r)), kTol * kmax * maxAbs(r) * 8.0);
}

// 2x2x2 block with moved interior, face and edge nodes; a linear displacement imposed on the
// 26 boundary nodes must be reproduced at the interior node, with a constant stress.
TEST(Hex8, PatchTestDistortedBlock) {
  auto index = [](int i, int j, int k) { return i + 3 * j + 9 * k; };
  std::vector<Point3> X(27);
  for (int k = 0; k < 3; ++k)
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i) X[index(i, j, k)] = {1.0 * i, 1.0 * j, 1.0 * k};
  X[index(1, 1, 1)] = {1.12, 0.91, 1.07};  // interior node
  X[index(1, 1, 0)] = {0.9, 1.15, 0.0};    // bottom face centre, moved in its plane
  X[index(2, 1, 1)] = {2.0, 1.1, 0.85};    // side face centre
  X[index(1, 0, 2)] = {1.2, 0.0, 2.0};     // edge midpoint, moved along its edge
  const auto R = someRotation();
  for (Point3& p : X) {
    p = rotate(R, p);
    p[0] += 0.5;
    p[2] -= 1.5;
  }
  // Linear field u = A x + b (not symmetric: includes a rotation).
  const std::array<Point3, 3> A = {
      Point3{1e-3, 2e-4, -3e-4}, Point3{-5e-4, 7e-4, 1.1e-3}, Point3{4e-4, -6e-4, -9e-4}};
  const Point3 b = {1e-3, -2e-3, 5e-4};
  auto exact = [&](const Point3& p) {
    return Point3{dot3(A[0], p) + b[0], dot3(A[1], p) + b[1], dot3(A[2], p) + b[2]};
  };

  auto el = makeHex8(kSteel);
  DenseMatrix K(81, 81);
  std::vector<std::vector<int>> elems;
  for (int k = 0; k < 2; ++k)
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i) {
        std::vector<int> c = {index(i, j, k),         index(i + 1, j, k),
                              index(i + 1, j + 1, k), index(i, j + 1, k),
                              index(i, j, k + 1),     index(i + 1, j, k + 1),
                              index(i + 1, j + 1, k + 1), index(i, j + 1, k + 1)};
        std::vector<Point3> xe;
        for (int n : c) xe.push_back(X[n]);
        DenseMatrix Ke;
        el->stiffness(xe, Ke);
        for (int a = 0; a < 8; ++a)
          for (int bb = 0; bb < 8; ++bb)
            for (int p = 0; p < 3; ++p)
              for (int q = 0; q < 3; ++q) K(3 * c[a] + p, 3 * c[bb] + q) += Ke(3 * a + p, 3 * bb + q);
        elems.push_back(c);
      }
  // Free DOFs: the interior node. K_ff u_f = -K_fb u_b.
  const int in = index(1, 1, 1);
  Vec u(81, 0.0);
  for (int n = 0; n < 27; ++n)
    if (n != in)
      for (int p = 0; p < 3; ++p) u[3 * n + p] = exact(X[n])[p];
  DenseMatrix Kff(3, 3);
  Vec rhs(3, 0.0);
  for (int p = 0; p < 3; ++p) {
    for (int q = 0; q < 3; ++q) Kff(p, q) = K(3 * in + p, 3 * in + q);
    for (int j = 0; j < 81; ++j) rhs[p] -= K(3 * in + p, j) * u[j];
  }
  const Vec uf = solve(Kff, rhs);
  const Point3 ue = exact(X[in]);
  const double uscale = maxAbs(u);
  for (int p = 0; p < 3; ++p) {
    EXPECT_NEAR(uf[p], ue[p], kTol * uscale);
    u[3 * in + p] = uf[p];
  }
  // Constant stress at every Gauss point of every element.
  const auto sExact = stress(kSteel, A);
  double smax = 0.0;
  for (const Point3& row : sExact)
    for (double v : row) smax = std::max(smax, std::fabs(v));
  for (const auto& c : elems) {
    std::vector<Point3> xe;
    for (int n : c) xe.push_back(X[n]);
    for (const Point3& gp : hex8GaussPoints()) {
      Hex8Gradients g;
      ASSERT_GT(hex8Gradients(xe, gp, g), 0.0);
      std::array<Point3, 3> grad{};
      for (int a = 0; a < 8; ++a)
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) grad[i][j] += u[3 * c[a] + i] * g[a][j];
      const auto s = stress(kSteel, grad);
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(s[i][j], sExact[i][j], kTol * smax);
    }
  }
}

// Box a x b x h, rotated; uniform strain eps along its axis n, no lateral displacement:
// the end-face force is E(1-nu)/((1+nu)(1-2nu)) eps a b.
TEST(Hex8, OedometricStrain) {
  const double a = 0.02, bw = 0.03, h = 0.05, eps = -2e-4;
  const auto R = someRotation();
  const Point3 x0 = {1.0, 2.0, -0.5};
  std::vector<Point3> x;
  const double corner[8][3] = {{0, 0, 0}, {a, 0, 0}, {a, bw, 0}, {0, bw, 0},
                               {0, 0, h}, {a, 0, h}, {a, bw, h}, {0, bw, h}};
  for (const auto& c : corner) {
    const Point3 q = rotate(R, {c[0], c[1], c[2]});
    x.push_back({q[0] + x0[0], q[1] + x0[1], q[2] + x0[2]});
  }
  const Point3 n = rotate(R, {0, 0, 1});
  Vec u(24);
  for (int k = 0; k < 8; ++k) {
    const double s = eps * dot3({x[k][0] - x0[0], x[k][1] - x0[1], x[k][2] - x0[2]}, n);
    for (int i = 0; i < 3; ++i) u[3 * k + i] = s * n[i];
  }
  DenseMatrix K;
  makeHex8(kSteel)->stiffness(x, K);
  const Vec f = multiply(K, u);
  Point3 top = {0, 0, 0}, bottom = {0, 0, 0};
  for (int k = 0; k < 8; ++k)
    for (int i = 0; i < 3; ++i) (k < 4 ? bottom : top)[i] += f[3 * k + i];
  const double E = kSteel.youngsModulus, nu = kSteel.poissonsRatio;
  const double F = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * eps * a * bw;
  EXPECT_NEAR(dot3(top, n), F, kTol * std::fabs(F));
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(top[i], F * n[i], kTol * std::fabs(F));  // no net lateral force
    EXPECT_NEAR(bottom[i], -F * n[i], kTol * std::fabs(F));
  }
}

TEST(Hex8, MassTotalsAndDefiniteness) {
  DistortedHex hex;
  auto el = makeHex8(kSteel);
  const double m = kSteel.density * hex.volume;
  for (MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
    SCOPED_TRACE(kind == MassKind::Consistent ? "consistent" : "lumped");
    DenseMatrix M;
    el->mass(hex.x, kind, M);
    ASSERT_EQ(M.rows(), 24);
    ASSERT_EQ(M.cols(), 24);
    const auto modes = rigidBodyModes(hex.x, 3, {0, 0, 0});
    for (int d = 0; d < 3; ++d) EXPECT_NEAR(quadratic(M, modes[d]), m, kTol * m);
    EXPECT_LE(asymmetry(M), kTol * maxAbs(M));
    if (kind == MassKind::Lumped) {
      for (int i = 0; i < 24; ++i) {
        EXPECT_GT(M(i, i), 0.0);
        for (int j = 0; j < 24; ++j)
          if (i != j) {
            EXPECT_EQ(M(i, j), 0.0) << i << "," << j;
          }
      }
    } else {
      const Vec ev = symmetricEigenvalues(M);
      EXPECT_GT(ev.front(), 1e-3 * ev.back());  // HEX8 consistent mass: cond = 27
      // Components do not couple.
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b)
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              if (i != j) {
            EXPECT_EQ(M(3 * a + i, 3 * b + j), 0.0);
          }
    }
  }
}

// For a rectangular box the consistent mass is the tensor product of [2 1; 1 2]/6:
// diagonal rho V/27, opposite corners rho V/216; lumped rho V/8.
TEST(Hex8, BoxMassEntries) {
  const auto R = someRotation();
  const double L[3] = {0.3, 0.5, 0.7};
  const double corner[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                               {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  std::vector<Point3> x;
  for (const auto& c : corner) x.push_back(rotate(R, {c[0] * L[0], c[1] * L[1], c[2] * L[2]}));
  const double m = kSteel.density * L[0] * L[1] * L[2];
  auto el = makeHex8(kSteel);
  DenseMatrix M;
  el->mass(x, MassKind::Consistent, M);
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(M(i, i), m / 27, kTol * m);
  EXPECT_NEAR(M(0, 3 * 6), m / 216, kTol * m);      // node 1 - node 7
  EXPECT_NEAR(M(3 * 1 + 2, 3 * 2 + 2), m / 54, kTol * m);  // nodes 2-3 share an edge
  el->mass(x, MassKind::Lumped, M);
  for (int i = 0; i < 24; ++i) EXPECT_NEAR(M(i, i), m / 8, kTol * m);
}

TEST(Hex8, InvertedOrDegenerateThrows) {
  const std::vector<Point3> cube = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                    {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  auto el = makeHex8(kSteel);
  DenseMatrix K;
  EXPECT_NO_THROW(el->stiffness(cube, K));
  // Top and bottom faces swapped: a mirror image, det J < 0 everywhere.
  std::vector<Point3> inverted(cube.begin() + 4, cube.end());
  inverted.insert(inverted.end(), cube.begin(), cube.begin() + 4);
  // Top face collapsed onto the bottom face: det J = 0.
  std::vector<Point3> flat(cube.begin(), cube.begin() + 4);
  flat.insert(flat.end(), cube.begin(), cube.begin() + 4);
  for (const auto* x : {&inverted, &flat}) {
    try {
      el->stiffness(*x, K);
      ADD_FAILURE() << "expected std::invalid_argument";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("inverted or degenerate HEX8"), std::string::npos)
          << e.what();
    }
    EXPECT_THROW(el->mass(*x, MassKind::Consistent, K), std::invalid_argument);
    EXPECT_THROW(el->mass(*x, MassKind::Lumped, K), std::invalid_argument);
  }
  EXPECT_THROW(el->stiffness({cube.begin(), cube.begin() + 7}, K), std::invalid_argument);
}
