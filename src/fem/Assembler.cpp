#include "fem/Assembler.hpp"
#include "fem/NormalMassRemoval.hpp"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <utility>

#include <Tpetra_CrsGraph.hpp>
#ifdef __GLIBC__
#include <malloc.h>
#endif
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

namespace choc {

Assembler::Assembler(const Mesh& mesh, const DofMap& dofs, std::vector<BlockPhysics> blocks,
                     RCP<const Comm> comm)
    : mesh_(mesh), dofs_(dofs), blocks_(std::move(blocks)), comm_(std::move(comm)) {
  const Tpetra::global_size_t n = static_cast<Tpetra::global_size_t>(dofs_.numGlobal());
  map_ = rcp(new Map(n, static_cast<size_t>(dofs_.numOwned()), 0, comm_));
  int global = 0;
  for (size_t b = 0; b < mesh_.blocks.size(); ++b) {
    const ElementBlock& blk = mesh_.blocks[b];
    for (int e = 0; e < blk.numElements(); ++e, ++global) {
      if (!blocks_[b].kernel) continue;
      const int* conn = &blk.connectivity[size_t(e) * blk.nodesPerElement];
      for (int k = 0; k < blk.nodesPerElement; ++k)
        if (dofs_.ownsNode(conn[k])) {
          elements_.push_back(global);
          break;
        }
    }
  }
}

std::vector<std::uint8_t> Assembler::carriedComponents(const Mesh& mesh,
                                                       const std::vector<BlockPhysics>& blocks) {
  std::vector<std::uint8_t> carried(mesh.numNodes(), 0);
  for (size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (!blocks[b].kernel) continue;
    std::uint8_t m = 0;
    for (int c : blocks[b].kernel->components()) m |= std::uint8_t(1u << c);
    for (int node : mesh.blocks[b].connectivity) carried[node] |= m;
  }
  return carried;
}

void redistributeElementMass(const std::vector<Point3>& x, const std::vector<char>& massless, int nc,
                             MassKind kind, DenseMatrix& Me) {
  const int nn = static_cast<int>(x.size());
  // to[k]: the nodes (and weights, summing to 1) whose motion node k follows in the mass.
  std::vector<std::vector<std::pair<int, double>>> to(nn);
  bool any = false;
  for (int k = 0; k < nn; ++k)
    if (massless[k]) any = true;
    else to[k] = {{k, 1.0}};
  if (!any) return;
  for (int k = 0; k < nn; ++k) {
    if (!massless[k]) continue;
    double dmin = std::numeric_limits<double>::infinity();
    std::vector<double> d(nn, dmin);
    for (int j = 0; j < nn; ++j) {
      if (massless[j]) continue;
      d[j] = 0.0;
      for (int c = 0; c < 3; ++c) d[j] += (x[k][c] - x[j][c]) * (x[k][c] - x[j][c]);
      dmin = std::min(dmin, d[j]);
    }
    if (!(dmin < std::numeric_limits<double>::infinity()))
      throw std::invalid_argument(
          "every node of an element lies on a contact surface: its mass cannot be redistributed "
          "(refine the mesh so that each element touching a contact surface has a node off it)");
    int count = 0;
    for (int j = 0; j < nn; ++j) count += d[j] <= dmin * (1 + 1e-8);
    for (int j = 0; j < nn; ++j)
      if (d[j] <= dmin * (1 + 1e-8)) to[k].emplace_back(j, 1.0 / count);
  }
  const int n = nn * nc;
  // R = Me T, then Me <- T^T R; T maps (node j, comp c) of the reduced motion to (node k, c).
  DenseMatrix R(n, n);
  for (int i = 0; i < n; ++i)
    for (int l = 0; l < n; ++l) {
      const double m = Me(i, l);
      if (m == 0.0) continue;
      for (const auto& [j, w] : to[l / nc]) R(i, j * nc + l % nc) += m * w;
    }
  DenseMatrix out(n, n);
  for (int i = 0; i < n; ++i)
    for (const auto& [j, w] : to[i / nc])
      for (int b = 0; b < n; ++b) out(j * nc + i % nc, b) += w * R(i, b);
  for (int a = 0; a < n; ++a)
    for (int b = 0; b < n; ++b)
      Me(a, b) = kind == MassKind::Lumped ? 0.0 : 0.5 * (out(a, b) + out(b, a));
  if (kind == MassKind::Lumped)  // keep a lumped matrix diagonal: row sums
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) Me(a, a) += out(a, b);
}

void Assembler::forEachElement(const std::function<void(const LocalElement&)>& fn) const {
  LocalElement el;
  for (int ge : elements_) {
    auto [b, e] = mesh_.locateElement(ge);
    const ElementBlock& blk = mesh_.blocks[b];
    el.physics = &blocks_[b];
    el.conn = &blk.connectivity[size_t(e) * blk.nodesPerElement];
    const auto& comps = el.physics->kernel->components();
    const int nc = static_cast<int>(comps.size());
    el.x.resize(blk.nodesPerElement);
    el.gdof.assign(size_t(blk.nodesPerElement) * nc, -1);
    for (int k = 0; k < blk.nodesPerElement; ++k) {
      el.x[k] = mesh_.coords[el.conn[k]];
      for (int j = 0; j < nc; ++j) el.gdof[k * nc + j] = dofs_.dof(el.conn[k], comps[j]);
    }
    fn(el);
  }
}

namespace {

using Graph = Tpetra::CrsGraph<LO, GO>;
// forEachRow(visit): calls visit(owned row) with the batch of one element's (or spring's)
// nonzero columns on that row in `cols`.
using RowVisitor = std::function<void(const std::function<void(int)>&)>;

// Sorts a row's column ids and removes the repeated ones.
template <class Index>
void compactPattern(std::vector<Index>& row) {
  std::sort(row.begin(), row.end());
  row.erase(std::unique(row.begin(), row.end()), row.end());
}

// Appends a batch of columns to a row, compacting it first when it is full, so that its
// capacity stays within about 1.5 times its distinct columns plus a batch.
template <class Index>
void appendPattern(std::vector<Index>& row, const std::vector<GO>& batch) {
  if (row.size() + batch.size() > row.capacity()) {
    compactPattern(row);
    const size_t need = row.size() + batch.size();
    if (need > row.capacity() * 2 / 3) row.reserve(need + need / 2);
  }
  for (GO c : batch) row.push_back(Index(c));
}

// The graph of the owned rows [first, first + owned): pass 1 over the elements. Index holds a
// column id while the pattern is gathered (32 bits when every id fits: half the memory).
template <class Index>
RCP<Graph> patternGraph(const RCP<const Map>& map, long long first, int owned, const RowVisitor& forEachRow,
                        const std::vector<GO>& cols) {
  std::vector<std::vector<Index>> pattern(owned);
  forEachRow([&](int r) { appendPattern(pattern[r], cols); });
  std::vector<size_t> counts(owned);
  for (int r = 0; r < owned; ++r) {
    compactPattern(pattern[r]);
    if (pattern[r].empty()) pattern[r].push_back(Index(first + r));  // keep the diagonal present
    counts[r] = pattern[r].size();
  }
  RCP<Graph> graph = rcp(new Graph(map, Teuchos::ArrayView<const size_t>(counts)));
  std::vector<GO> row;
  for (int r = 0; r < owned; ++r) {
    row.assign(pattern[r].begin(), pattern[r].end());
    graph->insertGlobalIndices(GO(first + r), Teuchos::ArrayView<const GO>(row));
    std::vector<Index>().swap(pattern[r]);
  }
  graph->fillComplete(map, map);
#ifdef __GLIBC__
  // The rows' pattern vectors (a few hundred bytes each) were freed inside the heap, which
  // keeps them resident: given back, the 300k-unknown scene's resident memory drops by 120 MiB.
  malloc_trim(0);
#endif
  return graph;
}

}  // namespace

// The rows the springs (k d d^T on each node) and the coupled node groups (zero entries between
// every DOF of a group) add after the elements: each as cols and vals, then visit(row).
void Assembler::extraRows(const std::vector<NodalSpring>& springs, bool coupled, std::vector<GO>& cols, std::vector<double>& vals,
                          const std::function<void(int)>& visit) const {
  const int owned = dofs_.numOwned();
  const long long first = dofs_.firstOwned();
  for (const NodalSpring& sp : springs)
    for (int i = 0; i < 3; ++i) {
      const long long gi = dofs_.dof(sp.node, i);
      if (gi < first || gi >= first + owned) continue;
      cols.clear();
      vals.clear();
      for (int j = 0; j < 3; ++j) {
        const long long gj = dofs_.dof(sp.node, j);
        const double kij = sp.stiffness * sp.direction[i] * sp.direction[j];
        if (gj >= 0 && kij != 0.0) cols.push_back(GO(gj)), vals.push_back(kij);
      }
      if (!cols.empty()) visit(int(gi - first));
    }
  if (!coupled) return;
  for (const std::vector<int>& group : groups_)  // zero entries coupling every DOF of a group
    for (int node : group)
      for (int i = 0; i < 3; ++i) {
        const long long gi = dofs_.dof(node, i);
        if (gi < first || gi >= first + owned) continue;
        cols.clear();
        vals.clear();
        for (int other : group)
          for (int j = 0; j < 3; ++j)
            if (dofs_.dof(other, j) >= 0) cols.push_back(GO(dofs_.dof(other, j))), vals.push_back(0.0);
        if (!cols.empty()) visit(int(gi - first));
      }
}

// Two passes over the elements, so that no element's entries are stored before they are summed
// (storing them took 16 bytes per element entry, about 3 times the matrix): the first finds
// each owned row's nonzero columns and makes the graph, the second sums the element matrices
// into the matrix on that graph. An entry is present when some element (or spring) gives it a
// nonzero value, and its value is the sum of those values in element order, then springs: the
// same graph and bits as summing a stored list. Each element matrix is computed twice, which
// costs less than the stored list's sort did (300k unknowns: 2.6 s against 3.2 s).
RCP<CrsMatrix> Assembler::assemble(const ElementMatrixFn& fn, const std::vector<NodalSpring>& springs,
                                   RCP<const Graph> graph, bool fullPatterns, bool coupled) const {
  const int owned = dofs_.numOwned();
  const long long first = dofs_.firstOwned();
  DenseMatrix Ke;
  std::vector<GO> cols;
  std::vector<double> vals;
  const RowVisitor forEachRow = [&](const std::function<void(int)>& visit) {
    forEachElement([&](const LocalElement& el) {
      fn(*el.physics->kernel, el.physics->mass, el.x, el.conn, Ke);
      const std::vector<long long>& gdof = el.gdof;
      const int n = static_cast<int>(gdof.size());
      const bool all = fullPatterns && el.physics->fullPattern;  // zero entries too (BlockPhysics)
      for (int i = 0; i < n; ++i) {
        const long long gi = gdof[i];
        if (gi < first || gi >= first + owned) continue;
        cols.clear();
        vals.clear();
        for (int j = 0; j < n; ++j)
          if (gdof[j] >= 0 && (all || Ke(i, j) != 0.0)) cols.push_back(GO(gdof[j])), vals.push_back(Ke(i, j));
        if (!cols.empty()) visit(int(gi - first));
      }
    });
    extraRows(springs, coupled, cols, vals, visit);
  };
  const bool narrow = dofs_.numGlobal() <= (long long)std::numeric_limits<std::uint32_t>::max();
  if (graph.is_null())
    graph = narrow ? patternGraph<std::uint32_t>(map_, first, owned, forEachRow, cols)
                   : patternGraph<GO>(map_, first, owned, forEachRow, cols);
  // Pass 2: the values on the graph, summed in element order.
  RCP<CrsMatrix> A = rcp(new CrsMatrix(graph));
  A->setAllToScalar(0.0);
  size_t missing = 0;
  forEachRow([&](int r) {
    const LO found = A->sumIntoGlobalValues(GO(first + r), Teuchos::ArrayView<const GO>(cols),
                                            Teuchos::ArrayView<const double>(vals));
    missing += cols.size() - size_t(found);
  });
  if (missing != 0) throw std::logic_error("assembly: " + std::to_string(missing) + " entries outside the pattern");
  A->fillComplete(map_, map_);
  return A;
}

RCP<CrsMatrix> Assembler::stiffness(const std::vector<NodalSpring>& springs) const {
  return stiffnessWithout({}, springs, RCP<const Graph>());
}

// The skipped blocks' elements, and a rigid block's (physics/RigidBodies.hpp), give no
// stiffness. A graph built here holds every entry of the full-pattern blocks (BlockPhysics).
RCP<CrsMatrix> Assembler::stiffnessWithout(const std::vector<char>& skip, const std::vector<NodalSpring>& springs,
                                           const RCP<const Graph>& graph) const {
  std::vector<const ElementKernel*> skipped;
  for (size_t b = 0; b < blocks_.size(); ++b)
    if ((b < skip.size() && skip[b]) || blocks_[b].rigid) skipped.push_back(blocks_[b].kernel.get());
  return assemble(
      [&](const ElementKernel& k, MassKind, const std::vector<Point3>& x, const int*, DenseMatrix& Ke) {
        if (std::find(skipped.begin(), skipped.end(), &k) == skipped.end()) return k.stiffness(x, Ke);
        const int n = static_cast<int>(x.size() * k.components().size());
        Ke.resize(n, n);
      },
      springs, graph, graph.is_null(), true);
}

RCP<CrsMatrix> Assembler::mass() const {
  return assemble([](const ElementKernel& k, MassKind m, const std::vector<Point3>& x, const int*,
                     DenseMatrix& Me) { k.mass(x, m, Me); });
}

RCP<CrsMatrix> Assembler::mass(const std::vector<char>& massless) const {
  if (massless.size() != static_cast<size_t>(mesh_.numNodes()))
    throw std::invalid_argument("mass redistribution: the massless-node mask has " +
                                std::to_string(massless.size()) + " entries for " +
                                std::to_string(mesh_.numNodes()) + " nodes");
  std::vector<char> local;
  return assemble([&](const ElementKernel& k, MassKind m, const std::vector<Point3>& x,
                      const int* conn, DenseMatrix& Me) {
    k.mass(x, m, Me);
    local.resize(x.size());
    for (size_t a = 0; a < x.size(); ++a) local[a] = massless[conn[a]];
    redistributeElementMass(x, local, static_cast<int>(k.components().size()), m, Me);
  });
}

RCP<CrsMatrix> Assembler::mass(const std::vector<std::vector<Point3>>& directions) const {
  if (directions.size() != static_cast<size_t>(mesh_.numNodes()))
    throw std::invalid_argument("normal contact mass: the directions cover " + std::to_string(directions.size()) +
                                " nodes of " + std::to_string(mesh_.numNodes()));
  std::vector<const std::vector<Point3>*> local;
  return assemble([&](const ElementKernel& k, MassKind m, const std::vector<Point3>& x, const int* conn,
                      DenseMatrix& Me) {
    k.mass(x, m, Me);
    local.resize(x.size());
    for (size_t a = 0; a < x.size(); ++a) local[a] = &directions[size_t(conn[a])];
    removeNormalMass(x, local, k.components(), m, Me);
  });
}


}  // namespace choc
