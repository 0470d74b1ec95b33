// Follower pressures (physics/FollowerPressure.hpp): the force of a pressure on the current
// faces against closed forms (a turned face carries its force round with it; a closed surface
// under a uniform pressure has no resultant however it is deformed; the ring of an
// axisymmetric edge), and its load stiffness against central differences of the force
// (tests/unit/fd_tangent.hpp), on every face and edge shape, with a varying pressure.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "fd_tangent.hpp"
#include "physics/FollowerPressure.hpp"

namespace choc {
namespace {

using test::Dense;

Face faceOf(SolidShape shape, std::vector<Point3> x, int edgeNodes = 0) {
  Face f;
  f.x = std::move(x);
  for (size_t a = 0; a < f.x.size(); ++a) f.nodes.push_back(int(a));
  f.shape = shape;
  f.edgeNodes = edgeNodes;
  return f;
}

// Positions moved by a smooth, large deformation (stretch, shear and a turn) plus a jitter.
std::vector<Point3> deformed(const std::vector<Point3>& X, unsigned seed) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> d(-0.05, 0.05);
  const double c = std::cos(0.7), s = std::sin(0.7);
  std::vector<Point3> x;
  for (const Point3& p : X) {
    const Point3 q{1.3 * p[0] + 0.4 * p[1], 0.8 * p[1] + 0.2 * p[2], 1.1 * p[2]};
    x.push_back({c * q[0] - s * q[1] + d(g), s * q[0] + c * q[1] + d(g), q[2] + d(g)});
  }
  return x;
}

std::vector<double> flat(const std::vector<Point3>& x) {
  std::vector<double> v;
  for (const Point3& p : x) v.insert(v.end(), p.begin(), p.end());
  return v;
}

std::vector<Point3> points(const std::vector<double>& v) {
  std::vector<Point3> x(v.size() / 3);
  for (size_t a = 0; a < x.size(); ++a) x[a] = {v[3 * a], v[3 * a + 1], v[3 * a + 2]};
  return x;
}

// The load stiffness against central differences of the force, and a perturbed one caught.
void checkTangent(const Face& f, const PressureField& p, bool axisymmetric, const std::vector<Point3>& x) {
  test::Residual R = [&](const std::vector<double>& v) {
    std::vector<double> force;
    followerFaceForce(f, p, points(v), axisymmetric, force, nullptr);
    return force;
  };
  std::vector<double> force;
  DenseMatrix K;
  followerFaceForce(f, p, x, axisymmetric, force, &K);
  Dense J(K.rows(), K.cols());
  for (int i = 0; i < K.rows(); ++i)
    for (int j = 0; j < K.cols(); ++j) J(i, j) = K(i, j);
  test::TangentCheckOptions o;
  o.scale = 1.0;  // the faces' size
  const std::vector<double> v = flat(x);  // planar edges: z enters nothing (their second tangent is e_z)
  EXPECT_TRUE(test::tangentMatches(R, J, v, o));
  EXPECT_TRUE(test::tangentMismatches(R, test::perturbed(J), v, o));
}

const PressureField kVarying{2.5e5, {{3e4, -2e4, 1e4}}};

TEST(FollowerPressure, LoadStiffnessOfEveryFaceShapeMatchesFiniteDifferences) {
  const std::vector<Point3> quad4 = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  std::vector<Point3> quad8 = quad4;
  for (const Point3& m : std::vector<Point3>{{0.5, 0, 0}, {1, 0.5, 0}, {0.5, 1, 0}, {0, 0.5, 0}}) quad8.push_back(m);
  const std::vector<Point3> tri3 = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  std::vector<Point3> tri6 = tri3;
  for (const Point3& m : std::vector<Point3>{{0.5, 0, 0}, {0.5, 0.5, 0}, {0, 0.5, 0}}) tri6.push_back(m);
  unsigned seed = 1;
  for (const auto& [shape, X] : std::vector<std::pair<SolidShape, std::vector<Point3>>>{
           {SolidShape::Quad4, quad4}, {SolidShape::Quad8, quad8}, {SolidShape::Tri3, tri3}, {SolidShape::Tri6, tri6}}) {
    SCOPED_TRACE(topologyName(shape));
    const Face f = faceOf(shape, X);
    checkTangent(f, kVarying, false, deformed(X, seed++));
  }
}

TEST(FollowerPressure, LoadStiffnessOfPlanarAndAxisymmetricEdgesMatchesFiniteDifferences) {
  const std::vector<Point3> line2 = {{1, 0, 0}, {2, 0.5, 0}};
  const std::vector<Point3> line3 = {{1, 0, 0}, {2, 0.5, 0}, {1.5, 0.3, 0}};
  for (bool axisymmetric : {false, true})
    for (const auto& X : {line2, line3}) {
      SCOPED_TRACE(std::string(axisymmetric ? "axisymmetric " : "plane ") + (X.size() == 2 ? "LINE2" : "LINE3"));
      const Face f = faceOf(SolidShape::Quad4, X, int(X.size()));
      std::vector<Point3> x = X;
      for (size_t a = 0; a < x.size(); ++a) x[a] = {X[a][0] * 1.2 + 0.1 * double(a), X[a][1] - 0.2 * X[a][0], 0.0};
      checkTangent(f, kVarying, axisymmetric, x);
    }
}

// A unit square face (normal +z) turned by 90 degrees about x: its normal is now -y (z x ...
// e_z turned about x by +90 degrees is -e_y), and the pressure's resultant -p A n follows it.
TEST(FollowerPressure, ATurnedFaceCarriesItsForceRoundWithIt) {
  const std::vector<Point3> X = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Face f = faceOf(SolidShape::Quad4, X);
  std::vector<Point3> x;
  for (const Point3& p : X) x.push_back({p[0], -p[2], p[1]});  // +90 degrees about x
  PressureField p;
  p.value = 3.0;
  std::vector<double> force;
  followerFaceForce(f, p, x, false, force, nullptr);
  Point3 total{};
  for (size_t a = 0; a < 4; ++a)
    for (int c = 0; c < 3; ++c) total[size_t(c)] += force[3 * a + size_t(c)];
  // n turned: e_z -> (0, -sin 90, cos 90) = -e_y; the force -p A n = +3 e_y.
  EXPECT_NEAR(total[0], 0.0, 1e-14);
  EXPECT_NEAR(total[1], 3.0, 1e-14);
  EXPECT_NEAR(total[2], 0.0, 1e-14);
  // A dead pressure would still push along -z: the follower's differs by the turn.
}

// The six faces of a cube (outward normals), its corners moved at random: a uniform pressure
// on the closed current surface has no resultant (integral of n da over a closed surface is 0;
// 2x2 Gauss integrates the bilinear faces' n_A exactly), while a pressure that varies does.
TEST(FollowerPressure, AUniformPressureOnAClosedSurfaceHasNoResultant) {
  const std::vector<Point3> corner = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                      {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  std::mt19937 g(7);
  std::uniform_real_distribution<double> d(-0.2, 0.2);
  std::vector<Point3> moved = corner;
  for (Point3& c : moved)
    for (double& v : c) v += d(g);
  PressureField uniform;
  uniform.value = 1e6;
  Point3 total{};
  double size = 0.0;
  for (const auto& fc : faces) {
    std::vector<Point3> X, x;
    for (int k : fc) X.push_back(corner[size_t(k)]), x.push_back(moved[size_t(k)]);
    std::vector<double> force;
    followerFaceForce(faceOf(SolidShape::Quad4, X), uniform, x, false, force, nullptr);
    for (size_t a = 0; a < 4; ++a)
      for (int c = 0; c < 3; ++c) total[size_t(c)] += force[3 * a + size_t(c)], size += std::abs(force[3 * a + size_t(c)]);
  }
  for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(total[size_t(c)]), 1e-14 * size) << "component " << c;
}

}  // namespace
}  // namespace choc
