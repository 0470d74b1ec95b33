// The two-bar impact mesh generator: counts, named nodes, geometry, orientation, validation.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <set>
#include <string>

#include "core/Errors.hpp"
#include "mesh/BarImpactMesh.hpp"

namespace {

using choc::BarImpactOptions;
using choc::Mesh;
using choc::Point3;

int axisIndex(char axis) { return axis - 'x'; }

int single(const Mesh& m, const std::string& set) {
  const choc::NodeSet* ns = m.findNodeSet(set);
  EXPECT_NE(ns, nullptr) << set;
  if (!ns) return -1;
  EXPECT_EQ(ns->nodes.size(), 1u) << set;
  return ns->nodes.empty() ? -1 : ns->nodes[0];
}

Point3 sub(const Point3& a, const Point3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double dot(const Point3& a, const Point3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

// det J of the trilinear map of a HEX8 at (xi, eta, zeta) in [-1,1]^3.
double hexJacobian(const Mesh& m, const int* n, double xi, double eta, double zeta) {
  static const int sign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                 {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
  double J[3][3] = {};
  for (int a = 0; a < 8; ++a) {
    const double sx = sign[a][0], sy = sign[a][1], sz = sign[a][2];
    const double d[3] = {sx * (1 + sy * eta) * (1 + sz * zeta) / 8,
                         sy * (1 + sx * xi) * (1 + sz * zeta) / 8,
                         sz * (1 + sx * xi) * (1 + sy * eta) / 8};
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) J[r][c] += d[r] * m.coords[n[a]][c];
  }
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
         J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

// Volume of a block by 2x2x2 Gauss quadrature (exact for trilinear hexahedra); every
// Gauss-point Jacobian must be positive.
double blockVolume(const Mesh& m, const choc::ElementBlock& b) {
  const double g = 1.0 / std::sqrt(3.0);
  double volume = 0.0;
  for (int e = 0; e < b.numElements(); ++e)
    for (double xi : {-g, g})
      for (double eta : {-g, g})
        for (double zeta : {-g, g}) {
          const double j = hexJacobian(m, &b.connectivity[8 * e], xi, eta, zeta);
          EXPECT_GT(j, 0.0) << b.name << " element " << e;
          volume += j;
        }
  return volume;
}

// Checks the side set's faces: right-hand-rule normal along expectedNormal and pointing
// away from the element's centroid; every face node at s = faceS.
void checkContactSides(const Mesh& m, const std::string& name, const Point3& expectedNormal,
                       int axis, double faceS, double faceArea, int expectedFaces) {
  const choc::SideSet* ss = m.findSideSet(name);
  ASSERT_NE(ss, nullptr) << name;
  ASSERT_EQ(static_cast<int>(ss->elements.size()), expectedFaces);
  double area = 0.0;
  for (std::size_t f = 0; f < ss->elements.size(); ++f) {
    const std::vector<int> face = m.sideNodes(ss->elements[f], ss->sides[f]);
    ASSERT_EQ(face.size(), 4u);
    for (int n : face) EXPECT_NEAR(m.coords[n][axis], faceS, 1e-12) << name;
    const Point3 normal = cross(sub(m.coords[face[2]], m.coords[face[0]]),
                                sub(m.coords[face[3]], m.coords[face[1]]));
    const double len = std::sqrt(dot(normal, normal));
    area += len / 2.0;
    EXPECT_NEAR(dot(normal, expectedNormal) / len, 1.0, 1e-12) << name << " face " << f;
    const auto [b, e] = m.locateElement(ss->elements[f]);
    Point3 centroid{0, 0, 0}, faceCentroid{0, 0, 0};
    for (int k = 0; k < 8; ++k)
      for (int d = 0; d < 3; ++d) centroid[d] += m.coords[m.blocks[b].connectivity[8 * e + k]][d] / 8;
    for (int n : face)
      for (int d = 0; d < 3; ++d) faceCentroid[d] += m.coords[n][d] / 4;
    EXPECT_GT(dot(normal, sub(faceCentroid, centroid)), 0.0) << name << " face " << f;
  }
  EXPECT_NEAR(area, faceArea, 1e-12 * faceArea + 1e-15);
}

TEST(BarImpactMesh, Standard1D) {
  BarImpactOptions o;
  const Mesh m = choc::generateBarImpactMesh(o);
  EXPECT_EQ(m.numNodes(), 102);
  EXPECT_EQ(m.numElements(), 100);
  ASSERT_EQ(m.blockNames(), (std::vector<std::string>{"POU1", "POU2"}));
  for (const auto& b : m.blocks) {
    EXPECT_EQ(b.topology, "BEAM2");
    EXPECT_EQ(b.numElements(), 50);
  }
  EXPECT_EQ(single(m, "A"), 0);
  EXPECT_EQ(single(m, "B"), 50);
  EXPECT_EQ(single(m, "C"), 51);
  EXPECT_EQ(single(m, "D"), 101);
  EXPECT_DOUBLE_EQ(m.coords[0][0], 1e-5);
  EXPECT_DOUBLE_EQ(m.coords[50][0], 1.0 + 1e-5);
  EXPECT_DOUBLE_EQ(m.coords[51][0], 0.0);
  EXPECT_DOUBLE_EQ(m.coords[101][0], -1.0);
  for (const Point3& p : m.coords) {
    EXPECT_EQ(p[1], 0.0);
    EXPECT_EQ(p[2], 0.0);
  }
  EXPECT_EQ(m.findNodeSet("POU1")->nodes.size(), 51u);
  EXPECT_EQ(m.findNodeSet("POU2")->nodes.size(), 51u);
  EXPECT_EQ(m.findNodeSet("POU2")->nodes.front(), 51);
  // Element lengths sum to the bar lengths, all positive; bars share no node.
  double l1 = 0.0, l2 = 0.0;
  for (int e = 0; e < 50; ++e) {
    const auto& c1 = m.blocks[0].connectivity;
    const auto& c2 = m.blocks[1].connectivity;
    const double d1 = m.coords[c1[2 * e + 1]][0] - m.coords[c1[2 * e]][0];
    const double d2 = m.coords[c2[2 * e]][0] - m.coords[c2[2 * e + 1]][0];
    EXPECT_GT(d1, 0.0);
    EXPECT_GT(d2, 0.0);
    l1 += d1;
    l2 += d2;
    EXPECT_GE(c2[2 * e], 51);
  }
  EXPECT_NEAR(l1, 1.0, 1e-14);
  EXPECT_NEAR(l2, 1.0, 1e-14);
}

TEST(BarImpactMesh, ShiftAMovesOnlyNodeA) {
  BarImpactOptions o;
  o.axis = 'y';
  const Mesh base = choc::generateBarImpactMesh(o);
  o.shiftA = -1.1e-5;
  const Mesh shifted = choc::generateBarImpactMesh(o);
  ASSERT_EQ(shifted.numNodes(), base.numNodes());
  EXPECT_NEAR(shifted.coords[0][1], -1e-6, 1e-18);  // A lies 1e-6 beyond C
  EXPECT_EQ(shifted.coords[0][0], 0.0);
  for (int n = 1; n < base.numNodes(); ++n) EXPECT_EQ(shifted.coords[n], base.coords[n]) << n;
}

TEST(BarImpactMesh, OneDimensionalAlongEachAxis) {
  for (char axis : {'x', 'y', 'z'}) {
    BarImpactOptions o;
    o.axis = axis;
    o.gap = 0.0;
    o.length1 = 2.0;
    o.length2 = 0.5;
    o.along1 = 4;
    o.along2 = 3;
    const Mesh m = choc::generateBarImpactMesh(o);
    const int a = axisIndex(axis);
    EXPECT_EQ(m.numNodes(), 9);
    EXPECT_EQ(m.numElements(), 7);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "A")][a], 0.0);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "B")][a], 2.0);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "C")][a], 0.0);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "D")][a], -0.5);
    EXPECT_NE(single(m, "A"), single(m, "C"));  // a zero gap still keeps two nodes
  }
}

TEST(BarImpactMesh, Standard3D) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  const Mesh m = choc::generateBarImpactMesh(o);
  EXPECT_EQ(m.numNodes(), 408);
  EXPECT_EQ(m.numElements(), 100);
  for (const auto& b : m.blocks) EXPECT_EQ(b.topology, "HEX8");
  const int z = 2;
  EXPECT_EQ(single(m, "N1"), single(m, "A"));
  const Point3 A = m.coords[single(m, "A")], C = m.coords[single(m, "C")];
  EXPECT_EQ(A, (Point3{0.0, 0.0, 1e-5}));
  EXPECT_EQ(C, (Point3{0.0, 0.0, 0.0}));
  EXPECT_EQ(m.coords[single(m, "B")], (Point3{0.0, 0.0, 1.0 + 1e-5}));
  EXPECT_EQ(m.coords[single(m, "D")], (Point3{0.0, 0.0, -1.0}));
  EXPECT_EQ(m.findNodeSet("POU1")->nodes.size(), 204u);
  EXPECT_EQ(m.findNodeSet("POU2")->nodes.size(), 204u);
  for (const char* face : {"CL_POU2", "FACE_POU1", "FACE_POU2"})
    EXPECT_EQ(m.findNodeSet(face)->nodes.size(), 4u) << face;
  for (int n : m.findNodeSet("CL_POU2")->nodes) EXPECT_EQ(m.coords[n][z], -1.0);
  for (int n : m.findNodeSet("FACE_POU1")->nodes) EXPECT_EQ(m.coords[n][z], 1e-5);
  for (int n : m.findNodeSet("FACE_POU2")->nodes) EXPECT_EQ(m.coords[n][z], 0.0);
  EXPECT_NEAR(blockVolume(m, m.blocks[0]), 4e-4, 1e-16);
  EXPECT_NEAR(blockVolume(m, m.blocks[1]), 4e-4, 1e-16);
  checkContactSides(m, "CNT_POU1", {0, 0, -1}, z, 1e-5, 4e-4, 1);
  checkContactSides(m, "CNT_POU2", {0, 0, 1}, z, 0.0, 4e-4, 1);
}

// 2 x 2 across bar 1, 3 x 3 across bar 2, 7 along each; width != height; every axis.
TEST(BarImpactMesh, Refined3DOnEveryAxis) {
  for (char axis : {'x', 'y', 'z'}) {
    BarImpactOptions o;
    o.dimension = 3;
    o.axis = axis;
    o.across1 = 2;
    o.across2 = 3;
    o.along1 = o.along2 = 7;
    o.width = 0.03;
    o.height = 0.02;
    o.length1 = 0.7;
    o.length2 = 1.4;
    o.gap = -2e-5;
    const Mesh m = choc::generateBarImpactMesh(o);
    const int a = axisIndex(axis), l1 = (a + 1) % 3, l2 = (a + 2) % 3;
    // nodes (along+1)(across+1)^2, elements along*across^2, per bar
    EXPECT_EQ(m.numNodes(), 8 * 9 + 8 * 16) << axis;
    EXPECT_EQ(m.numElements(), 7 * 4 + 7 * 9) << axis;
    EXPECT_EQ(m.findNodeSet("FACE_POU1")->nodes.size(), 9u);
    EXPECT_EQ(m.findNodeSet("FACE_POU2")->nodes.size(), 16u);
    EXPECT_EQ(m.findNodeSet("CL_POU2")->nodes.size(), 16u);
    EXPECT_EQ(m.findNodeSet("POU1")->nodes.size(), 72u);
    EXPECT_EQ(m.findNodeSet("POU2")->nodes.size(), 128u);
    // Section extents along the cyclic lateral axes.
    double max1 = 0.0, max2 = 0.0;
    for (const Point3& p : m.coords) {
      max1 = std::max(max1, p[l1]);
      max2 = std::max(max2, p[l2]);
      EXPECT_GE(p[l1], 0.0);
      EXPECT_GE(p[l2], 0.0);
    }
    EXPECT_DOUBLE_EQ(max1, 0.03);
    EXPECT_DOUBLE_EQ(max2, 0.02);
    const Point3 A = m.coords[single(m, "A")];
    EXPECT_DOUBLE_EQ(A[a], -2e-5);
    EXPECT_EQ(A[l1], 0.0);
    EXPECT_EQ(A[l2], 0.0);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "B")][a], -2e-5 + 0.7);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "C")][a], 0.0);
    EXPECT_DOUBLE_EQ(m.coords[single(m, "D")][a], -1.4);
    const double section = 0.03 * 0.02;
    EXPECT_NEAR(blockVolume(m, m.blocks[0]), 0.7 * section, 1e-15);
    EXPECT_NEAR(blockVolume(m, m.blocks[1]), 1.4 * section, 1e-15);
    Point3 minus{0, 0, 0}, plus{0, 0, 0};
    minus[a] = -1.0;
    plus[a] = 1.0;
    checkContactSides(m, "CNT_POU1", minus, a, -2e-5, section, 4);
    checkContactSides(m, "CNT_POU2", plus, a, 0.0, section, 9);
    // No node is used twice in a set; every node belongs to an element.
    std::set<int> used;
    for (const auto& b : m.blocks) used.insert(b.connectivity.begin(), b.connectivity.end());
    EXPECT_EQ(static_cast<int>(used.size()), m.numNodes());
  }
}

TEST(BarImpactMesh, LargeMeshIsFast) {
  BarImpactOptions o;
  o.dimension = 3;
  o.across1 = o.across2 = 8;
  o.along1 = o.along2 = 400;
  const auto start = std::chrono::steady_clock::now();
  const Mesh m = choc::generateBarImpactMesh(o);
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(m.numNodes(), 2 * 401 * 81);
  EXPECT_EQ(m.numElements(), 2 * 400 * 64);
  EXPECT_EQ(m.findSideSet("CNT_POU1")->elements.size(), 64u);
  EXPECT_LT(seconds, 2.0);
}

std::string validationMessage(const BarImpactOptions& o) {
  try {
    choc::validateBarImpactOptions(o);
  } catch (const choc::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BarImpactMesh, ValidationNamesTheOption) {
  BarImpactOptions o;
  EXPECT_EQ(validationMessage(o), "");
  o.length1 = 0.0;
  EXPECT_EQ(validationMessage(o).rfind("choc mesh: parameter '--length1' = '0': must be", 0), 0u)
      << validationMessage(o);
  o = {};
  o.length2 = -1.0;
  EXPECT_NE(validationMessage(o).find("'--length2' = '-1'"), std::string::npos);
  o = {};
  o.width = std::nan("");
  EXPECT_NE(validationMessage(o).find("'--width'"), std::string::npos);
  o = {};
  o.along2 = 0;
  EXPECT_NE(validationMessage(o).find("parameter '--along2' = '0': must be an integer >= 1"),
            std::string::npos);
  o = {};
  o.across1 = 0;
  EXPECT_NE(validationMessage(o).find("'--across1' = '0'"), std::string::npos);
  o = {};
  o.axis = 'w';
  EXPECT_EQ(validationMessage(o), "choc mesh: parameter '--axis' = 'w': must be x, y or z; "
                                  "give the axis of the bars");
  o = {};
  o.dimension = 2;
  EXPECT_NE(validationMessage(o).find("'--dim' = '2'"), std::string::npos);
  o = {};
  o.gap = INFINITY;
  EXPECT_NE(validationMessage(o).find("'--gap'"), std::string::npos);
  o = {};
  o.dimension = 3;
  o.shiftA = -1.1e-5;
  EXPECT_NE(validationMessage(o).find("'--shift-a'"), std::string::npos);
  o = {};
  o.shiftA = 0.02;  // onto the second node (element length 0.02)
  EXPECT_NE(validationMessage(o).find("'--shift-a'"), std::string::npos);
  o = {};
  o.dimension = 3;
  o.across1 = 100000;
  EXPECT_NE(validationMessage(o).find("'--across1'"), std::string::npos);
  // Zero and negative gaps are valid test cases.
  for (double gap : {0.0, -1e-5}) {
    o = {};
    o.gap = gap;
    o.dimension = 3;
    EXPECT_EQ(validationMessage(o), "");
  }
  // generate validates too.
  o = {};
  o.along1 = 0;
  EXPECT_THROW(choc::generateBarImpactMesh(o), choc::InputError);
  // every message is one line
  o = {};
  o.axis = '\n';
  EXPECT_EQ(validationMessage(o).find('\n'), std::string::npos);
}

}  // namespace
