#include "physics/DegenerateElements.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Vec3.hpp"
#include "fem/IsoparametricPoint.hpp"
#include "fem/ShapeFunctions.hpp"

namespace choc {

namespace {

// A relative size below which a corner's Jacobian counts as zero: the round-off of a determinant of
// coordinates of unit size, far below any element a mesher writes (its shape ratio near 1e10).
constexpr double kZeroJacobian = 1e-10;

// The first node index that appears twice among an element's nodes (-1: none).
int repeatedNode(const int* nodes, int n) {
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b)
      if (nodes[a] == nodes[b]) return nodes[a];
  return -1;
}

// The solid's smallest corner Jacobian relative to its largest, and the corner (1-based). An
// element whose corners are all negative is inverted as a whole (its node order), which the
// element's own check reports: +infinity then.
std::pair<double, int> smallestCornerJacobian(SolidShape t, const std::vector<Point3>& x) {
  const std::vector<Point3>& xi = nodeNaturalCoordinates(t);
  double smallest = INFINITY, largest = -INFINITY;
  int corner = 0;
  for (int a = 0; a < cornerCount(t); ++a) {
    const double det = jacobianDeterminant(t, x, xi[size_t(a)]);
    largest = std::max(largest, det);
    if (det < smallest) smallest = det, corner = a + 1;
  }
  if (largest < 0) return {INFINITY, corner};
  return {largest > 0 ? smallest / largest : 0.0, corner};
}

// Two corners at one place (relative to the element's largest corner distance): the corners.
std::pair<int, int> coincidentCorners(SolidShape t, const std::vector<Point3>& x) {
  const int c = cornerCount(t);
  double largest = 0.0;
  for (int a = 0; a < c; ++a)
    for (int b = a + 1; b < c; ++b) largest = std::max(largest, norm(x[size_t(a)] - x[size_t(b)]));
  for (int a = 0; a < c; ++a)
    for (int b = a + 1; b < c; ++b)
      if (norm(x[size_t(a)] - x[size_t(b)]) <= kZeroJacobian * largest) return {a + 1, b + 1};
  return {0, 0};
}

}  // namespace

void checkDegenerateElements(const Mesh& mesh, const std::string& inputFile, const std::string& meshFile) {
  int first = 0;
  for (const ElementBlock& blk : mesh.blocks) {
    const int n = blk.nodesPerElement;
    SolidShape shape{};
    const bool solid = findSolidTopology(blk.topology, shape);
    std::vector<Point3> x(static_cast<size_t>(n));
    for (int e = 0; e < blk.numElements(); ++e) {
      const int* nodes = blk.connectivity.data() + size_t(e) * size_t(n);
      const std::string where = "block '" + blk.name + "', element " + std::to_string(first + e + 1) + " (" +
                                blk.topology + "): ";
      if (const int twice = repeatedNode(nodes, n); twice >= 0)
        throwInput(inputFile, "Mesh/File", meshFile,
                   where + "node " + std::to_string(twice + 1) +
                       " appears twice in its connectivity (a degenerate element: a wedge or pyramid written as a "
                       "hexahedron?)",
                   "mesh it with elements whose nodes are distinct (choc has no wedge or pyramid)");
      if (!solid) continue;
      for (int a = 0; a < n; ++a) x[size_t(a)] = mesh.coords[size_t(nodes[a])];
      if (const auto [a, b] = coincidentCorners(shape, x); a > 0)
        throwInput(inputFile, "Mesh/File", meshFile,
                   where + format("corners %d and %d (nodes %d and %d) are at one place: the element is degenerate", a,
                                  b, nodes[a - 1] + 1, nodes[b - 1] + 1),
                   "fix the element in the mesh (merging the two nodes would make it a wedge, which choc has not)");
      if (isQuadratic(shape)) continue;  // a quarter-point element's corner Jacobian is 0 by design
      const auto [relative, corner] = smallestCornerJacobian(shape, x);
      if (relative > kZeroJacobian) continue;
      throwInput(inputFile, "Mesh/File", meshFile,
                 where + format("degenerate or folded: the Jacobian at corner %d is %.3g of the largest corner's", corner,
                                relative) +
                     " (two corners at one place, a face with no area, or the element folded over itself)",
                 "fix the element in the mesh");
    }
    first += blk.numElements();
  }
}

}  // namespace choc
