// Isoparametric continuum elements, one element at a time, for every topology and
// kinematics on affine, distorted (non-affine), curved and on-axis geometries: rigid modes
// and rank, mass totals, lumping, definiteness, closed-form strain energy, agreement with
// the HEX8 kernel, and input errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>

#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/SolidElement.hpp"
#include "test_fem_solid_cases.hpp"

using namespace choc;
using namespace choc::test;

namespace {

constexpr double kTol = 1e-10;  // relative round-off bound for element-size sums
const Material kSteel{2e11, 0.3, 7800.0};

int componentsOf(Kinematics k) { return k == Kinematics::ThreeD ? 3 : 2; }

// Rigid motions: 3D the 6 of test_fem_helpers; plane strain 2 translations and the rotation
// about z; axisymmetric only the axial translation.
std::vector<Vec> rigidModes(const ElementCase& c) {
  if (c.kinematics == Kinematics::ThreeD) return rigidBodyModes(c.x, 3, {-0.7, 1.9, 0.35});
  const size_t n = c.x.size();
  std::vector<Vec> modes;
  for (int d = (c.kinematics == Kinematics::Axisymmetric ? 1 : 0); d < 2; ++d) {
    Vec r(2 * n, 0.0);
    for (size_t a = 0; a < n; ++a) r[2 * a + d] = 1.0;
    modes.push_back(r);
  }
  if (c.kinematics == Kinematics::PlaneStrain) {
    Vec r(2 * n);
    for (size_t a = 0; a < n; ++a) {
      r[2 * a] = -(c.x[a][1] - 0.3);
      r[2 * a + 1] = c.x[a][0] + 0.2;
    }
    modes.push_back(r);
  }
  return modes;
}

// A field of constant strain and its exact strain energy 1/2 int sigma : eps dV.
// 3D and plane strain: u = A x + b. Axisymmetric: u_r = a r, u_z = c r + b z + d, so
// e_rr = e_tt = a, e_zz = b, gamma_rz = c.
Vec constantStrainField(const ElementCase& c, double& energy) {
  const double E = kSteel.youngsModulus, nu = kSteel.poissonsRatio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  const double A[3][3] = {{1.0e-3, -2.0e-4, 5e-4}, {3e-4, 7e-4, -1.2e-3}, {-4e-4, 1.5e-3, 2e-4}};
  const double b[3] = {1e-3, -2e-3, 5e-4};
  const int nc = componentsOf(c.kinematics);
  Vec u(c.x.size() * nc);
  double trace = 0.0, eps2 = 0.0;  // tr(eps), eps : eps
  if (c.kinematics == Kinematics::Axisymmetric) {
    const double a = A[0][0], bz = A[1][1], g = A[1][0];
    for (size_t n = 0; n < c.x.size(); ++n) {
      u[2 * n] = a * c.x[n][0];
      u[2 * n + 1] = g * c.x[n][0] + bz * c.x[n][1] + b[1];
    }
    trace = 2 * a + bz;
    eps2 = 2 * a * a + bz * bz + g * g / 2;
  } else {
    for (size_t n = 0; n < c.x.size(); ++n)
      for (int i = 0; i < nc; ++i) {
        u[nc * n + i] = b[i];
        for (int j = 0; j < nc; ++j) u[nc * n + i] += A[i][j] * c.x[n][j];
      }
    for (int i = 0; i < nc; ++i) {
      trace += A[i][i];
      for (int j = 0; j < nc; ++j) eps2 += std::pow((A[i][j] + A[j][i]) / 2, 2);
    }
  }
  energy = 0.5 * (lambda * trace * trace + 2 * mu * eps2) * c.measure;
  return u;
}

std::string thrownMessage(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(nothing thrown)";
}

class SolidElementCase : public ::testing::TestWithParam<ElementCase> {};

// Symmetric; K r = 0 for the rigid modes; no other zero-energy mode.
void checkStiffnessRigidModesAndRank(const ElementCase& c) {
  DenseMatrix K;
  makeSolidElement(c.topology, c.kinematics, kSteel)->stiffness(c.x, K);
  const int nd = static_cast<int>(c.x.size()) * componentsOf(c.kinematics);
  ASSERT_EQ(K.rows(), nd);
  ASSERT_EQ(K.cols(), nd);
  const double kmax = maxAbs(K);
  EXPECT_LE(asymmetry(K), kTol * kmax);
  const std::vector<Vec> modes = rigidModes(c);
  for (const Vec& r : modes) EXPECT_LE(maxAbs(multiply(K, r)), kTol * kmax * maxAbs(r) * nd);
  // Rank: exactly as many zero eigenvalues as rigid modes, none negative.
  const Vec ev = symmetricEigenvalues(K);
  EXPECT_GE(ev.front(), -kTol * ev.back());
  int zeros = 0;
  for (double l : ev) zeros += l < kTol * ev.back();
  EXPECT_EQ(zeros, static_cast<int>(modes.size()));
}

// 1/2 u^T K u of a constant-strain field equals 1/2 sigma : eps times the measure.
void checkConstantStrainEnergy(const ElementCase& c) {
  DenseMatrix K;
  makeSolidElement(c.topology, c.kinematics, kSteel)->stiffness(c.x, K);
  double energy = 0.0;
  const Vec u = constantStrainField(c, energy);
  EXPECT_NEAR(0.5 * quadratic(K, u), energy, kTol * energy);
}

// 1_c^T M 1_c = rho * measure for each component c, consistent and lumped.
void checkMassTotals(const ElementCase& c) {
  EXPECT_NEAR(solidElementMeasure(c.topology, c.kinematics, c.x), c.measure, kTol * c.measure);
  auto el = makeSolidElement(c.topology, c.kinematics, kSteel);
  const int nc = componentsOf(c.kinematics);
  const double m = kSteel.density * c.measure;
  for (MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
    SCOPED_TRACE(kind == MassKind::Consistent ? "consistent" : "lumped");
    DenseMatrix M;
    el->mass(c.x, kind, M);
    ASSERT_EQ(M.rows(), static_cast<int>(c.x.size()) * nc);
    for (int comp = 0; comp < nc; ++comp) {
      Vec one(M.rows(), 0.0);
      for (size_t a = 0; a < c.x.size(); ++a) one[a * nc + comp] = 1.0;
      EXPECT_NEAR(quadratic(M, one), m, kTol * m) << "component " << comp;
    }
  }
}

// Symmetric, block-diagonal by component, positive definite.
void checkConsistentMass(const ElementCase& c) {
  DenseMatrix M;
  makeSolidElement(c.topology, c.kinematics, kSteel)->mass(c.x, MassKind::Consistent, M);
  EXPECT_LE(asymmetry(M), kTol * maxAbs(M));
  const int nc = componentsOf(c.kinematics);
  for (int i = 0; i < M.rows(); ++i)
    for (int j = 0; j < M.cols(); ++j) {
      if (i % nc != j % nc) {
        EXPECT_EQ(M(i, j), 0.0) << i << "," << j;
      }
    }
  const Vec ev = symmetricEigenvalues(M);
  EXPECT_GT(ev.front(), kTol * ev.back());  // Jacobi round-off is ~1e-15 ev.back()
}

// Lumped: diagonal, strictly positive; row sums of the consistent mass for linear
// topologies, the consistent diagonal scaled (HRZ) for quadratic ones.
void checkLumpedMass(const ElementCase& c) {
  auto el = makeSolidElement(c.topology, c.kinematics, kSteel);
  DenseMatrix L, M;
  el->mass(c.x, MassKind::Lumped, L);
  el->mass(c.x, MassKind::Consistent, M);
  const bool quadratic = !exodusEdges(c.topology).empty();
  const double scale = maxAbs(M);
  const double ratio = L(0, 0) / M(0, 0);
  double minRowSum = scale;
  for (int i = 0; i < L.rows(); ++i) {
    EXPECT_GT(L(i, i), 0.0) << i;
    double rowSum = 0.0;
    for (int j = 0; j < L.cols(); ++j) {
      if (i != j) {
        EXPECT_EQ(L(i, j), 0.0) << i << "," << j;
      }
      rowSum += M(i, j);
    }
    minRowSum = std::min(minRowSum, rowSum);
    EXPECT_NEAR(L(i, i), quadratic ? ratio * M(i, i) : rowSum, kTol * scale) << i;
  }
  // Why HRZ: the consistent row sums of TET10 and HEX20 corners are negative.
  if (c.topology == "TET10" || c.topology == "HEX20") {
    EXPECT_LT(minRowSum, 0.0);
  }
}

// Two nodes swapped, or all nodes in a plane (3D) / on a line (2D).
void checkInvertedOrDegenerateThrows(const ElementCase& c) {
  auto el = makeSolidElement(c.topology, c.kinematics, kSteel);
  std::vector<Point3> swapped = c.x;
  std::swap(swapped[0], swapped[1]);
  std::vector<Point3> flat = c.x;  // all nodes on a line (2D) or a plane (3D)
  for (Point3& p : flat) p[c.kinematics == Kinematics::ThreeD ? 2 : 1] = 0.5;
  for (const auto& x : {swapped, flat}) {
    DenseMatrix K;
    const std::string stiff = thrownMessage([&] { el->stiffness(x, K); });
    EXPECT_NE(stiff.find("inverted or degenerate " + c.topology + " element"), std::string::npos)
        << stiff;
    const std::string mass = thrownMessage([&] { el->mass(x, MassKind::Lumped, K); });
    EXPECT_NE(mass.find("inverted or degenerate " + c.topology + " element"), std::string::npos)
        << mass;
  }
}

}  // namespace

TEST_P(SolidElementCase, StiffnessRigidModesRankEnergyAndInversion) {
  const ElementCase& c = GetParam();
  checkStiffnessRigidModesAndRank(c);
  checkConstantStrainEnergy(c);
  checkInvertedOrDegenerateThrows(c);
}

TEST_P(SolidElementCase, MassTotalsDefinitenessAndLumping) {
  const ElementCase& c = GetParam();
  checkMassTotals(c);
  checkConsistentMass(c);
  checkLumpedMass(c);
}

INSTANTIATE_TEST_SUITE_P(AllTopologies, SolidElementCase, ::testing::ValuesIn(allElementCases()));

TEST(SolidElement, ComponentsAndNodeCounts) {
  const std::vector<std::pair<std::string, int>> topologies = {
      {"TET4", 4}, {"TET10", 10}, {"HEX8", 8},  {"HEX20", 20},
      {"TRI3", 3}, {"TRI6", 6},   {"QUAD4", 4}, {"QUAD8", 8}};
  for (const auto& [name, nodes] : topologies) {
    const bool threeD = name[0] == 'T' ? name.rfind("TET", 0) == 0 : name[0] == 'H';
    for (Kinematics k : {Kinematics::ThreeD, Kinematics::PlaneStrain, Kinematics::Axisymmetric}) {
      if (threeD != (k == Kinematics::ThreeD)) continue;
      auto el = makeSolidElement(name, k, kSteel);
      EXPECT_EQ(el->numNodes(), nodes) << name;
      EXPECT_EQ(el->components(),
                threeD ? std::vector<int>({DX, DY, DZ}) : std::vector<int>({DX, DY}));
    }
  }
  EXPECT_EQ(makeSolidElement("tetra", Kinematics::ThreeD, kSteel)->numNodes(), 4);
  EXPECT_STREQ(toString(Kinematics::ThreeD), "3D");
  EXPECT_STREQ(toString(Kinematics::PlaneStrain), "plane strain");
  EXPECT_STREQ(toString(Kinematics::Axisymmetric), "axisymmetric");
}

// makeSolidElement("HEX8", ThreeD) and makeHex8 use the same interpolation and 2x2x2 rule.
TEST(SolidElement, Hex8AgreesWithTheHex8Kernel) {
  double volume = 0.0;
  const std::vector<Point3> x = distortedHexCorners(volume);
  auto solid = makeSolidElement("HEX8", Kinematics::ThreeD, kSteel);
  auto hex8 = makeHex8(kSteel);
  DenseMatrix A, B;
  solid->stiffness(x, A);
  hex8->stiffness(x, B);
  ASSERT_EQ(A.rows(), B.rows());
  double diff = 0.0;
  for (int i = 0; i < A.rows(); ++i)
    for (int j = 0; j < A.cols(); ++j) diff = std::max(diff, std::fabs(A(i, j) - B(i, j)));
  EXPECT_LE(diff, 1e-12 * maxAbs(B));
  for (MassKind kind : {MassKind::Consistent, MassKind::Lumped}) {
    solid->mass(x, kind, A);
    hex8->mass(x, kind, B);
    diff = 0.0;
    for (int i = 0; i < A.rows(); ++i)
      for (int j = 0; j < A.cols(); ++j) diff = std::max(diff, std::fabs(A(i, j) - B(i, j)));
    EXPECT_LE(diff, 1e-12 * maxAbs(B));
  }
}

TEST(SolidElement, TopologyMustMatchKinematics) {
  const std::string m1 =
      thrownMessage([] { makeSolidElement("QUAD4", Kinematics::ThreeD, kSteel); });
  EXPECT_NE(m1.find("QUAD4"), std::string::npos) << m1;
  EXPECT_NE(m1.find("3D"), std::string::npos) << m1;
  const std::string m2 =
      thrownMessage([] { makeSolidElement("HEX8", Kinematics::PlaneStrain, kSteel); });
  EXPECT_NE(m2.find("HEX8"), std::string::npos) << m2;
  EXPECT_NE(m2.find("plane strain"), std::string::npos) << m2;
  const std::string m3 =
      thrownMessage([] { makeSolidElement("TET10", Kinematics::Axisymmetric, kSteel); });
  EXPECT_NE(m3.find("TET10"), std::string::npos) << m3;
  EXPECT_NE(m3.find("axisymmetric"), std::string::npos) << m3;
  EXPECT_THROW(makeSolidElement("TRI6", Kinematics::ThreeD, kSteel), std::invalid_argument);
  EXPECT_THROW(makeSolidElement("SHELL4", Kinematics::PlaneStrain, kSteel), std::invalid_argument);
  EXPECT_THROW(makeSolidElement("BEAM2", Kinematics::ThreeD, kSteel), std::invalid_argument);
}

TEST(SolidElement, MaterialOutOfRangeThrows) {
  for (const Material& m :
       {Material{0.0, 0.3, 7800}, Material{-1e9, 0.3, 7800}, Material{2e11, 0.5, 7800},
        Material{2e11, -1.0, 7800}, Material{2e11, 0.3, -1.0}})
    for (const char* topo : {"TET4", "QUAD8"}) {
      const Kinematics k = topo[0] == 'T' ? Kinematics::ThreeD : Kinematics::Axisymmetric;
      const std::string msg = thrownMessage([&] { makeSolidElement(topo, k, m); });
      EXPECT_NE(msg.find(std::string(topo) + " element: "), std::string::npos) << msg;
      EXPECT_NE(msg.find("must be"), std::string::npos) << msg;
    }
  EXPECT_NO_THROW(makeSolidElement("TET4", Kinematics::ThreeD, Material{2e11, 0.499, 0.0}));
}

TEST(SolidElement, AxisymmetricNegativeRadiusThrows) {
  auto el = makeSolidElement("QUAD4", Kinematics::Axisymmetric, kSteel);
  const std::vector<Point3> x = {{-0.2, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-0.2, 1, 0}};
  DenseMatrix K;
  const std::string ms = thrownMessage([&] { el->stiffness(x, K); });
  EXPECT_NE(ms.find("axisymmetric elements need x = r >= 0"), std::string::npos) << ms;
  const std::string mm = thrownMessage([&] { el->mass(x, MassKind::Consistent, K); });
  EXPECT_NE(mm.find("axisymmetric elements need x = r >= 0"), std::string::npos) << mm;
  // The same element is valid in plane strain.
  EXPECT_NO_THROW(makeSolidElement("QUAD4", Kinematics::PlaneStrain, kSteel)->stiffness(x, K));
}

// A QUAD8 collapsed into a triangle (nodes 3, 4 and 7 coincide) has det J = 0 at two corners
// only: accepted, with the triangle's area.
TEST(SolidElement, CollapsedQuadraticElementIsAccepted) {
  const std::vector<Point3> c = {{0.1, 0.2, 0}, {1.3, 0.4, 0}, {0.5, 1.2, 0}, {0.5, 1.2, 0}};
  const std::vector<Point3> x = withMidEdgeNodes("QUAD8", c);
  const double area = polygonArea({c[0], c[1], c[2]});
  EXPECT_NEAR(solidElementMeasure("QUAD8", Kinematics::PlaneStrain, x), area, kTol * area);
  DenseMatrix M;
  EXPECT_NO_THROW(
      makeSolidElement("QUAD8", Kinematics::PlaneStrain, kSteel)->mass(x, MassKind::Lumped, M));
}

TEST(SolidElement, WrongNodeCountThrows) {
  auto el = makeSolidElement("TET10", Kinematics::ThreeD, kSteel);
  DenseMatrix K;
  EXPECT_THROW(el->stiffness(std::vector<Point3>(4, Point3{0, 0, 0}), K), std::invalid_argument);
}
