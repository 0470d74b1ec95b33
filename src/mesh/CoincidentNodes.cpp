#include "mesh/CoincidentNodes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace choc {

namespace {

double shortestEdge(const Mesh& mesh) {
  double h = std::numeric_limits<double>::infinity();
  for (const ElementBlock& b : mesh.blocks)
    for (int e = 0; e < b.numElements(); ++e) {
      const int* c = &b.connectivity[static_cast<std::size_t>(e) * b.nodesPerElement];
      for (int k = 1; k < b.nodesPerElement; ++k) {
        const double d = norm(mesh.coords[c[k]] - mesh.coords[c[0]]);
        if (d > 0) h = std::min(h, d);
      }
    }
  return h;
}

std::vector<int> nodesOnElements(const Mesh& mesh) {
  std::vector<char> used(mesh.coords.size(), 0);
  for (const ElementBlock& b : mesh.blocks)
    for (int n : b.connectivity) used[n] = 1;
  std::vector<int> nodes;
  for (std::size_t n = 0; n < used.size(); ++n)
    if (used[n]) nodes.push_back(static_cast<int>(n));
  return nodes;
}

}  // namespace

CoincidentNodes findCoincidentNodes(const Mesh& mesh, double relativeTolerance) {
  CoincidentNodes out;
  const double h = shortestEdge(mesh);
  if (!std::isfinite(h)) return out;
  out.tolerance = relativeTolerance * h;
  // Cells of twice the tolerance: two coincident nodes are in the same or neighbouring cells.
  const double cell = 2.0 * out.tolerance;
  using Key = std::tuple<long long, long long, long long>;
  std::map<Key, std::vector<int>> grid;
  const auto keyOf = [&](const Point3& p) {
    return Key{std::llround(std::floor(p[0] / cell)), std::llround(std::floor(p[1] / cell)),
               std::llround(std::floor(p[2] / cell))};
  };
  const std::vector<int> nodes = nodesOnElements(mesh);
  for (int n : nodes) grid[keyOf(mesh.coords[n])].push_back(n);
  std::vector<int> keptFor(mesh.coords.size(), -1);
  for (int n : nodes) {
    if (keptFor[n] >= 0) continue;
    const auto [x, y, z] = keyOf(mesh.coords[n]);
    for (long long i = x - 1; i <= x + 1; ++i)
      for (long long j = y - 1; j <= y + 1; ++j)
        for (long long k = z - 1; k <= z + 1; ++k) {
          const auto it = grid.find(Key{i, j, k});
          if (it == grid.end()) continue;
          for (int m : it->second)
            if (m > n && keptFor[m] < 0 && norm(mesh.coords[m] - mesh.coords[n]) <= out.tolerance) {
              keptFor[m] = n;
              out.pairs.emplace_back(n, m);
            }
        }
  }
  std::sort(out.pairs.begin(), out.pairs.end(),
            [](const auto& a, const auto& b) { return a.second < b.second; });
  return out;
}

void mergeCoincidentNodes(Mesh& mesh, const CoincidentNodes& found) {
  std::vector<int> to(mesh.coords.size());
  for (std::size_t n = 0; n < to.size(); ++n) to[n] = static_cast<int>(n);
  for (const auto& [kept, duplicate] : found.pairs) to[duplicate] = kept;
  for (ElementBlock& b : mesh.blocks)
    for (int& n : b.connectivity) n = to[n];
  for (NodeSet& s : mesh.nodeSets) {
    std::vector<int> merged;
    for (int n : s.nodes)
      if (std::find(merged.begin(), merged.end(), to[n]) == merged.end()) merged.push_back(to[n]);
    s.nodes = std::move(merged);
  }
}

}  // namespace choc
