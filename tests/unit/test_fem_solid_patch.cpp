// Patch tests of the continuum elements: a box meshed with several distorted elements of one
// topology (interior vertices moved off-centre, mid-edge nodes at the edge midpoints), the
// exact displacement of a constant-stress state imposed on the boundary nodes; the interior
// nodes solved from the assembled stiffness must take the same field.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <utility>

#include "fem/SolidElement.hpp"
#include "test_fem_solid_cases.hpp"

using namespace choc;
using namespace choc::test;

namespace {

const Material kSteel{2e11, 0.3, 7800.0};

struct PatchMesh {
  std::vector<Point3> x;
  std::vector<std::vector<int>> elements;
};

// (n + 1)^dim grid nodes on the box [lo, hi], node (i, j, k) at i + (n+1) (j + (n+1) k);
// interior nodes moved by up to `shift` cell sizes in each direction.
PatchMesh gridNodes(int dim, int n, const Point3& lo, const Point3& hi, double shift) {
  PatchMesh m;
  const int nk = dim == 3 ? n + 1 : 1;
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i <= n; ++i) {
        const int g[3] = {i, j, k};
        bool interior = true;
        Point3 p = {0, 0, 0};
        for (int d = 0; d < dim; ++d) {
          p[d] = lo[d] + (hi[d] - lo[d]) * g[d] / n;
          interior = interior && g[d] > 0 && g[d] < n;
        }
        const double id = static_cast<double>(m.x.size());
        for (int d = 0; d < dim && interior; ++d)
          p[d] += shift * (hi[d] - lo[d]) / n * std::sin(2.3 * id + 1.7 * d + 0.5);
        m.x.push_back(p);
      }
  return m;
}

// Corner connectivity of the cells: QUAD4 / HEX8 one element per cell, TRI3 two triangles,
// TET4 the six tetrahedra of the Kuhn (Freudenthal) subdivision, which conforms across cells.
void addCells(PatchMesh& m, int dim, int n, const std::string& linear) {
  auto g = [n](int i, int j, int k) { return i + (n + 1) * (j + (n + 1) * k); };
  const int nk = dim == 3 ? n : 1;
  for (int k = 0; k < nk; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int v[8] = {
            g(i, j, k),     g(i + 1, j, k),     g(i + 1, j + 1, k),     g(i, j + 1, k),
            g(i, j, k + 1), g(i + 1, j, k + 1), g(i + 1, j + 1, k + 1), g(i, j + 1, k + 1)};
        if (linear == "QUAD4") m.elements.push_back({v[0], v[1], v[2], v[3]});
        if (linear == "HEX8") m.elements.push_back(std::vector<int>(v, v + 8));
        if (linear == "TRI3") {
          m.elements.push_back({v[0], v[1], v[2]});
          m.elements.push_back({v[0], v[2], v[3]});
        }
        if (linear != "TET4") continue;
        int axes[3] = {0, 1, 2};
        do {  // the path (0,0,0) -> +e_a0 -> +e_a1 -> (1,1,1)
          int c[3] = {i, j, k};
          std::vector<int> tet = {g(c[0], c[1], c[2])};
          for (int s = 0; s < 3; ++s) {
            ++c[axes[s]];
            tet.push_back(g(c[0], c[1], c[2]));
          }
          if (tetVolume(m.x[tet[0]], m.x[tet[1]], m.x[tet[2]], m.x[tet[3]]) < 0)
            std::swap(tet[1], tet[2]);
          m.elements.push_back(tet);
        } while (std::next_permutation(axes, axes + 3));
      }
}

// One node at the midpoint of every element edge, shared between the elements.
void addMidEdgeNodes(PatchMesh& m, const std::string& topology) {
  std::map<std::pair<int, int>, int> made;
  for (std::vector<int>& e : m.elements) {
    const std::vector<int> corners = e;
    for (const auto& [a, b] : exodusEdges(topology)) {
      const std::pair<int, int> key = std::minmax(corners[a], corners[b]);
      auto it = made.find(key);
      if (it == made.end()) {
        it = made.emplace(key, static_cast<int>(m.x.size())).first;
        m.x.push_back(midpoint(m.x[key.first], m.x[key.second]));
      }
      e.push_back(it->second);
    }
  }
}

// Boundary nodes lie on a face of the box (the moved nodes are interior vertices; a
// mid-edge node is on a face exactly when both ends of its edge are on that face).
std::vector<bool> boundaryNodes(const PatchMesh& m, int dim, const Point3& lo, const Point3& hi) {
  std::vector<bool> b(m.x.size(), false);
  for (size_t a = 0; a < m.x.size(); ++a)
    for (int d = 0; d < dim; ++d) {
      const double tol = 1e-12 * (hi[d] - lo[d]);
      b[a] = b[a] || std::fabs(m.x[a][d] - lo[d]) < tol || std::fabs(m.x[a][d] - hi[d]) < tol;
    }
  return b;
}

// Dense global stiffness, node-major DOFs (nc per node).
DenseMatrix assemble(const PatchMesh& m, const ElementKernel& el, int nc) {
  const int n = static_cast<int>(m.x.size()) * nc;
  DenseMatrix K(n, n);
  DenseMatrix Ke;
  for (const std::vector<int>& e : m.elements) {
    std::vector<Point3> xe;
    for (int node : e) xe.push_back(m.x[node]);
    el.stiffness(xe, Ke);
    for (size_t a = 0; a < e.size(); ++a)
      for (size_t b = 0; b < e.size(); ++b)
        for (int i = 0; i < nc; ++i)
          for (int j = 0; j < nc; ++j)
            K(e[a] * nc + i, e[b] * nc + j) +=
                Ke(static_cast<int>(a) * nc + i, static_cast<int>(b) * nc + j);
  }
  return K;
}

// Imposes `exact` on the boundary nodes, solves K_ff u_f = -K_fb u_b and returns the largest
// difference from `exact` at the free DOFs relative to the largest displacement. `free`
// counts the free DOFs.
double patchError(const PatchMesh& m, const std::vector<bool>& boundary, const DenseMatrix& K,
                  int nc, const std::function<Point3(const Point3&)>& exact, int& free) {
  std::vector<int> f;
  Vec u(K.rows(), 0.0);
  for (size_t a = 0; a < m.x.size(); ++a) {
    const Point3 ua = exact(m.x[a]);
    for (int i = 0; i < nc; ++i) {
      u[a * nc + i] = ua[i];
      if (!boundary[a]) f.push_back(static_cast<int>(a) * nc + i);
    }
  }
  free = static_cast<int>(f.size());
  DenseMatrix Kff(free, free);
  Vec rhs(free, 0.0);
  for (int p = 0; p < free; ++p) {
    for (int q = 0; q < free; ++q) Kff(p, q) = K(f[p], f[q]);
    for (int j = 0; j < K.cols(); ++j)
      if (boundary[j / nc]) rhs[p] -= K(f[p], j) * u[j];
  }
  const Vec uf = solve(Kff, rhs);
  double err = 0.0;
  for (int p = 0; p < free; ++p) err = std::max(err, std::fabs(uf[p] - u[f[p]]));
  return err / maxAbs(u);
}

struct PatchCase {
  std::string label, topology;
  Kinematics kinematics;
  Point3 lo, hi;
};

std::string linearOf(const std::string& topology) {
  const std::map<std::string, std::string> linear = {
      {"TET10", "TET4"}, {"HEX20", "HEX8"}, {"TRI6", "TRI3"}, {"QUAD8", "QUAD4"}};
  const auto it = linear.find(topology);
  return it == linear.end() ? topology : it->second;
}

std::vector<PatchCase> patchCases() {
  std::vector<PatchCase> c;
  for (const char* t : {"TET4", "TET10", "HEX8", "HEX20"})
    c.push_back({std::string(t) + "_3D", t, Kinematics::ThreeD, {0.2, -0.1, 0.3}, {1.2, 1.1, 1.0}});
  for (const char* t : {"TRI3", "TRI6", "QUAD4", "QUAD8"}) {
    c.push_back(
        {std::string(t) + "_plane", t, Kinematics::PlaneStrain, {0.5, -0.2, 0}, {1.5, 0.9, 0}});
    c.push_back(
        {std::string(t) + "_axi", t, Kinematics::Axisymmetric, {1.0, 0.0, 0}, {2.0, 1.0, 0}});
    c.push_back({std::string(t) + "_axi_on_axis",
                 t,
                 Kinematics::Axisymmetric,
                 {0.0, -0.5, 0},
                 {1.0, 0.7, 0}});
  }
  return c;
}

void PrintTo(const PatchCase& c, std::ostream* os) { *os << c.label; }  // names ctest tests

class SolidPatch : public ::testing::TestWithParam<PatchCase> {};

}  // namespace

// 3D and plane strain: u = A x + b with a general (non-symmetric) A. Axisymmetric:
// u_r = a r, u_z = b z + c, whose stress (sigma_rr = sigma_tt, sigma_zz constant) is in
// equilibrium without body force.
TEST_P(SolidPatch, InteriorNodesReproduceConstantStressField) {
  const PatchCase& c = GetParam();
  const int dim = c.kinematics == Kinematics::ThreeD ? 3 : 2, n = 3;
  PatchMesh m = gridNodes(dim, n, c.lo, c.hi, linearOf(c.topology) == "TET4" ? 0.1 : 0.2);
  addCells(m, dim, n, linearOf(c.topology));
  addMidEdgeNodes(m, c.topology);
  const std::vector<bool> boundary = boundaryNodes(m, dim, c.lo, c.hi);
  auto el = makeSolidElement(c.topology, c.kinematics, kSteel);
  const int nc = dim;
  const DenseMatrix K = assemble(m, *el, nc);
  const double A[3][3] = {{1.0e-3, -2.0e-4, 5e-4}, {3e-4, 7e-4, -1.2e-3}, {-4e-4, 1.5e-3, 2e-4}};
  const double b[3] = {1e-3, -2e-3, 5e-4};
  auto exact = [&](const Point3& x) {
    Point3 u = {0, 0, 0};
    if (c.kinematics == Kinematics::Axisymmetric)
      return Point3{A[0][0] * x[0], A[1][1] * x[1] + b[1], 0};
    for (int i = 0; i < dim; ++i) {
      u[i] = b[i];
      for (int j = 0; j < dim; ++j) u[i] += A[i][j] * x[j];
    }
    return u;
  };
  int free = 0;
  EXPECT_LE(patchError(m, boundary, K, nc, exact, free), 1e-9);
  EXPECT_GE(free, 4 * nc);  // several interior nodes
}

INSTANTIATE_TEST_SUITE_P(AllTopologies, SolidPatch, ::testing::ValuesIn(patchCases()));
