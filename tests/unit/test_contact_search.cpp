// The search on a master surface (SurfaceSearch): closest points on a flat grid of QUAD4 faces
// against their closed form, the binned search equal to a brute-force loop over every face on
// a curved surface of TRI3 faces, the same gaps after a rigid motion of surface and points,
// and nothing found beyond the reach.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <random>

#include "contact/SurfaceSearch.hpp"

namespace choc {
namespace {

// n x n QUAD4 faces on [0, 1]^2 at z = 0, counter-clockwise seen from +z (normal +z).
std::vector<Face> flatGrid(int n) {
  std::vector<Face> faces;
  auto id = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      Face f;
      f.shape = SolidShape::Quad4;
      f.nodes = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
      for (int k : f.nodes) f.x.push_back({double(k % (n + 1)) / n, double(k / (n + 1)) / n, 0.0});
      faces.push_back(f);
    }
  return faces;
}

// A half cylinder of radius r about the y axis (x = r sin a, z = r cos a, a in [-pi/2, pi/2]),
// m facets around and m along y in [0, 1], each quadrilateral cut into two TRI3, normals out.
std::vector<Face> halfCylinder(int m, double r) {
  std::vector<Face> faces;
  auto id = [m](int i, int j) { return j * (m + 1) + i; };
  auto at = [m, r](int i, int j) {
    const double a = -M_PI / 2 + M_PI * i / m;
    return Point3{r * std::sin(a), double(j) / m, r * std::cos(a)};
  };
  for (int j = 0; j < m; ++j)
    for (int i = 0; i < m; ++i)
      for (const auto& tri : {std::array<std::pair<int, int>, 3>{{{i, j}, {i + 1, j}, {i, j + 1}}},
                              std::array<std::pair<int, int>, 3>{{{i + 1, j}, {i + 1, j + 1}, {i, j + 1}}}}) {
        Face f;
        f.shape = SolidShape::Tri3;
        for (const auto& [a, b] : tri) {
          f.nodes.push_back(id(a, b));
          f.x.push_back(at(a, b));
        }
        faces.push_back(f);
      }
  return faces;
}

// Every face projected: the nearest containing its projection with |gap| <= reach.
bool bruteForce(const std::vector<Face>& faces, const Point3& x, double reach, SurfaceHit& hit) {
  double best = std::numeric_limits<double>::infinity();
  bool found = false;
  for (size_t k = 0; k < faces.size(); ++k) {
    double xi, eta;
    if (!projectOnFace(faces[k], x, xi, eta) || !insideFace(faces[k], xi, eta)) continue;
    const FacePoint q = evaluateFace(faces[k], xi, eta);
    const Point3 d = x - q.x;
    Point3 n = cross(q.dxi, q.deta);
    const double len = norm(n);
    for (double& v : n) v /= len;
    if (norm(d) < best - 1e-15 && std::abs(dot(d, n)) <= reach) {
      best = norm(d);
      found = true;
      hit.face = int(k);
      hit.gap = dot(d, n);
    }
  }
  return found;
}

TEST(SurfaceSearch, ClosestPointOnAFlatGridIsTheVerticalProjection) {
  const int n = 10;
  const SurfaceSearch s(flatGrid(n), 0.05);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0.001, 0.999), h(-0.04, 0.04);
  for (int k = 0; k < 200; ++k) {
    const Point3 x{u(rng), u(rng), h(rng)};
    SurfaceHit hit;
    ASSERT_TRUE(s.closest(x, hit));
    EXPECT_EQ(hit.face, int(x[1] * n) * n + int(x[0] * n));
    EXPECT_NEAR(hit.gap, x[2], 1e-14);
    EXPECT_NEAR(hit.normal[2], 1.0, 1e-14);
    double sum = 0.0;
    for (double w : hit.N) sum += w;
    EXPECT_NEAR(sum, 1.0, 1e-14);
  }
  SurfaceHit hit;
  EXPECT_FALSE(s.closest({0.5, 0.5, 0.06}, hit));   // beyond the reach
  EXPECT_FALSE(s.closest({1.2, 0.5, 0.0}, hit));    // beside the surface
}

TEST(SurfaceSearch, BinnedSearchEqualsEveryFaceProjectedOnACurvedSurface) {
  const double r = 0.3, reach = 0.02;
  const std::vector<Face> faces = halfCylinder(24, r);
  const SurfaceSearch s(faces, reach);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> a(-1.4, 1.4), y(0.01, 0.99), h(-0.019, 0.019);
  int found = 0;
  for (int k = 0; k < 300; ++k) {
    const double ang = a(rng), rad = r + h(rng);
    const Point3 x{rad * std::sin(ang), y(rng), rad * std::cos(ang)};
    SurfaceHit binned, brute;
    const bool fb = s.closest(x, binned), fr = bruteForce(faces, x, reach, brute);
    ASSERT_EQ(fb, fr) << "point " << k;
    if (!fb) continue;  // over a convex kink: no face contains the projection
    ++found;
    EXPECT_EQ(binned.face, brute.face);
    EXPECT_EQ(binned.gap, brute.gap);
    // The facets are chords, inside the circle: the gap is the radial offset plus at most the
    // facets' sagitta r (1 - cos(pi / 48)).
    EXPECT_GE(binned.gap, rad - r - 1e-12);
    EXPECT_LE(binned.gap, rad - r + r * (1 - std::cos(M_PI / 48)) + 1e-12);
  }
  EXPECT_GT(found, 250);
  EXPECT_GT(s.projections(), 0);
  EXPECT_LT(s.projections(), 300LL * 1152 / 10);  // a bin's faces per point, not all 1,152
}

TEST(SurfaceSearch, GapsAreTheSameAfterARigidMotionOfSurfaceAndPoints) {
  const double r = 0.3, reach = 0.02;
  const std::vector<Face> faces = halfCylinder(16, r);
  SurfaceSearch moved(faces, reach);
  const SurfaceSearch still(faces, reach);
  // A rotation of 0.7 rad about (1, 2, 2)/3 and a translation.
  const Vec3 k{1.0 / 3, 2.0 / 3, 2.0 / 3}, t{0.4, -1.3, 2.2};
  const double c = std::cos(0.7), sn = std::sin(0.7);
  auto move = [&](const Point3& p) {
    const Vec3 kxp = cross(k, p);
    const double kp = dot(k, p);
    Point3 q;
    for (int d = 0; d < 3; ++d) q[d] = p[d] * c + kxp[d] * sn + k[d] * kp * (1 - c) + t[d];
    return q;
  };
  std::map<int, Point3> at;
  for (const Face& f : faces)
    for (size_t i = 0; i < f.nodes.size(); ++i) at[f.nodes[i]] = move(f.x[i]);
  moved.moveTo([&](int node) { return at.at(node); });
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> a(-1.4, 1.4), y(0.01, 0.99), h(-0.019, 0.019);
  for (int k2 = 0; k2 < 100; ++k2) {
    const double ang = a(rng), rad = r + h(rng);
    const Point3 x{rad * std::sin(ang), y(rng), rad * std::cos(ang)};
    SurfaceHit h0, h1;
    const bool f0 = still.closest(x, h0), f1 = moved.closest(move(x), h1);
    ASSERT_EQ(f0, f1);
    if (!f0) continue;
    EXPECT_EQ(h0.face, h1.face);
    EXPECT_NEAR(h0.gap, h1.gap, 1e-13);
  }
}

}  // namespace
}  // namespace choc

namespace choc {
namespace {

// onFace (the face a followed slave node keeps, FollowedSurfaces::find): a point just past the
// edge between faces 0 and 1 of a 2 x 2 grid (x = 0.5 + 2.5e-4, that is xi = 1 + 1e-3 on face
// 0's parameters of half-width 0.25) is kept on face 0 with its widening 2e-3 and not with
// 5e-4, and the search alone gives face 1, the one containing it.
TEST(SurfaceSearch, AFaceIsKeptJustPastItsEdgeWithinTheWidening) {
  SurfaceSearch s(flatGrid(2), 0.1);
  const Point3 x{0.5 + 2.5e-4, 0.25, 0.01};
  SurfaceHit hit;
  ASSERT_TRUE(s.closest(x, hit));
  EXPECT_EQ(hit.face, 1);
  ASSERT_TRUE(s.onFace(0, x, hit, 2e-3));
  EXPECT_EQ(hit.face, 0);
  EXPECT_NEAR(hit.xi, 1.0 + 1e-3, 1e-12);
  EXPECT_NEAR(hit.gap, 0.01, 1e-15);
  EXPECT_FALSE(s.onFace(0, x, hit, 5e-4));
  EXPECT_FALSE(s.onFace(-1, x, hit, 1.0));  // no current face
}

}  // namespace
}  // namespace choc
