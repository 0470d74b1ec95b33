// The distributing coupling's load (physics/CouplingLoad.hpp): on nodes placed anyhow its forces
// have the resultant F and the moment M about their centroid, its derivative is the central
// differences of the forces, and a moment on nodes along a line is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/CouplingLoad.hpp"

namespace choc {
namespace {

// Seven nodes of a turned, stretched face and one off it (not symmetric about their centroid).
std::vector<Point3> someNodes() {
  return {{0.1, 0.02, -0.03}, {0.35, 0.1, 0.02}, {0.12, 0.31, 0.05}, {0.4, 0.38, -0.02},
          {0.25, 0.2, 0.15},  {0.05, 0.22, 0.1}, {0.3, -0.05, 0.07}};
}

TEST(CouplingLoad, ItsForcesHaveTheResultantAndTheMomentAboutTheCentroid) {
  const std::vector<Point3> x = someNodes();
  const Vec3 F = {3.0, -2.0, 5.0}, M = {-40.0, 25.0, 60.0};
  std::vector<double> f;
  couplingForce(x, F, M, f, nullptr);
  Vec3 c{}, R{}, T{};
  for (const Point3& p : x)
    for (int d = 0; d < 3; ++d) c[d] += p[d] / double(x.size());
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3 fi = {f[3 * i], f[3 * i + 1], f[3 * i + 2]};
    const Vec3 m = cross(x[i] - c, fi);
    for (int d = 0; d < 3; ++d) R[d] += fi[d], T[d] += m[d];
  }
  // round-off of sums of forces of size |M| / |r| ~ 300 N
  for (int d = 0; d < 3; ++d) {
    EXPECT_NEAR(R[d], F[d], 1e-12 * 300) << d;
    EXPECT_NEAR(T[d], M[d], 1e-12 * 300) << d;
  }
}

TEST(CouplingLoad, ItsLoadStiffnessIsTheCentralDifferencesOfItsForces) {
  const std::vector<Point3> x = someNodes();
  const Vec3 F = {3.0, -2.0, 5.0}, M = {-40.0, 25.0, 60.0};
  std::vector<double> f, fp, fm;
  DenseMatrix K;
  couplingForce(x, F, M, f, &K);
  const double h = 1e-6;  // of a 0.4 m set: the differences' truncation (h/L)^2 ~ 1e-11, round-off eps/h ~ 1e-10
  double worst = 0.0, peak = 0.0;
  for (size_t k = 0; k < x.size(); ++k)
    for (int q = 0; q < 3; ++q) {
      std::vector<Point3> xp = x, xm = x;
      xp[k][q] += h;
      xm[k][q] -= h;
      couplingForce(xp, F, M, fp, nullptr);
      couplingForce(xm, F, M, fm, nullptr);
      for (size_t i = 0; i < 3 * x.size(); ++i) {
        const double fd = (fp[i] - fm[i]) / (2 * h);
        worst = std::max(worst, std::abs(fd - K(int(i), int(3 * k) + q)));
        peak = std::max(peak, std::abs(fd));
      }
    }
  EXPECT_GT(peak, 100.0);  // the load stiffness is not small: ~ |M| / |r|^2
  EXPECT_LE(worst, 1e-6 * peak);
}

// BENCHMARKS section 8: the nodes turned (with F and M) give the turned forces; the nodes listed
// in another order give the same force on each node (round-off of sums of ~300 N).
TEST(CouplingLoad, ItsForcesTurnWithTheSceneAndDoNotDependOnTheNodesOrder) {
  const std::vector<Point3> x = someNodes();
  const Vec3 F = {3.0, -2.0, 5.0}, M = {-40.0, 25.0, 60.0};
  const double c = std::cos(0.7), s = std::sin(0.7);  // about the axis (1, 1, 1) / sqrt 3
  const double k = 1.0 / 3.0;
  const double R[3][3] = {{c + k * (1 - c), k * (1 - c) - s / std::sqrt(3.0), k * (1 - c) + s / std::sqrt(3.0)},
                          {k * (1 - c) + s / std::sqrt(3.0), c + k * (1 - c), k * (1 - c) - s / std::sqrt(3.0)},
                          {k * (1 - c) - s / std::sqrt(3.0), k * (1 - c) + s / std::sqrt(3.0), c + k * (1 - c)}};
  const auto turn = [&](const Vec3& v) {
    Vec3 w{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) w[i] += R[i][j] * v[j];
    return w;
  };
  std::vector<Point3> xt, xr(x.rbegin(), x.rend());
  for (const Point3& p : x) xt.push_back(turn(p));
  std::vector<double> f, ft, fr;
  couplingForce(x, F, M, f, nullptr);
  couplingForce(xt, turn(F), turn(M), ft, nullptr);
  couplingForce(xr, F, M, fr, nullptr);
  for (size_t i = 0; i < x.size(); ++i) {
    const Vec3 expected = turn({f[3 * i], f[3 * i + 1], f[3 * i + 2]});
    const size_t j = x.size() - 1 - i;
    for (int d = 0; d < 3; ++d) {
      EXPECT_NEAR(ft[3 * i + d], expected[d], 1e-12 * 300) << i << " " << d;
      EXPECT_NEAR(fr[3 * j + d], f[3 * i + d], 1e-12 * 300) << i << " " << d;
    }
  }
}

TEST(CouplingLoad, AMomentOnNodesAlongALineIsRefused) {
  const std::vector<Point3> line = {{0, 0, 0}, {0.1, 0.1, 0}, {0.3, 0.3, 0}};
  std::vector<double> f;
  EXPECT_THROW(couplingForce(line, {1, 0, 0}, {0, 0, 5}, f, nullptr), std::invalid_argument);
  couplingForce(line, {3, 0, 0}, {0, 0, 0}, f, nullptr);  // a force alone: shared equally
  EXPECT_DOUBLE_EQ(f[0], 1.0);
  EXPECT_DOUBLE_EQ(f[6], 1.0);
}

}  // namespace
}  // namespace choc
