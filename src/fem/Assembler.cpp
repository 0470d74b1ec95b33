#include "fem/Assembler.hpp"

#include <algorithm>
#include <utility>

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

RCP<CrsMatrix> Assembler::assemble(const ElementMatrixFn& fn) const {
  const int owned = dofs_.numOwned();
  const long long first = dofs_.firstOwned();
  std::vector<std::vector<std::pair<GO, double>>> rows(owned);
  std::vector<Point3> x;
  std::vector<long long> gdof;
  DenseMatrix Ke;
  for (int ge : elements_) {
    auto [b, e] = mesh_.locateElement(ge);
    const ElementBlock& blk = mesh_.blocks[b];
    const ElementKernel& kernel = *blocks_[b].kernel;
    const int* conn = &blk.connectivity[size_t(e) * blk.nodesPerElement];
    const auto& comps = kernel.components();
    const int nc = static_cast<int>(comps.size());
    x.resize(blk.nodesPerElement);
    gdof.assign(size_t(blk.nodesPerElement) * nc, -1);
    for (int k = 0; k < blk.nodesPerElement; ++k) {
      x[k] = mesh_.coords[conn[k]];
      for (int j = 0; j < nc; ++j) gdof[k * nc + j] = dofs_.dof(conn[k], comps[j]);
    }
    fn(kernel, blocks_[b].mass, x, Ke);
    const int n = static_cast<int>(gdof.size());
    for (int i = 0; i < n; ++i) {
      const long long gi = gdof[i];
      if (gi < first || gi >= first + owned) continue;
      auto& row = rows[gi - first];
      for (int j = 0; j < n; ++j)
        if (gdof[j] >= 0 && Ke(i, j) != 0.0) row.emplace_back(GO(gdof[j]), Ke(i, j));
    }
  }
  // Combine duplicates; stable sort keeps element order, so sums do not depend on ranks.
  std::vector<size_t> counts(owned);
  for (int r = 0; r < owned; ++r) {
    auto& row = rows[r];
    std::stable_sort(row.begin(), row.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    size_t w = 0;
    for (size_t i = 0; i < row.size(); ++i) {
      if (w > 0 && row[w - 1].first == row[i].first) row[w - 1].second += row[i].second;
      else row[w++] = row[i];
    }
    row.resize(w);
    if (row.empty()) row.emplace_back(GO(first + r), 0.0);  // keep the diagonal present
    counts[r] = row.size();
  }
  RCP<CrsMatrix> A = rcp(new CrsMatrix(map_, Teuchos::ArrayView<const size_t>(counts)));
  std::vector<GO> cols;
  std::vector<double> vals;
  for (int r = 0; r < owned; ++r) {
    cols.clear();
    vals.clear();
    for (const auto& [c, v] : rows[r]) {
      cols.push_back(c);
      vals.push_back(v);
    }
    A->insertGlobalValues(GO(first + r), Teuchos::ArrayView<const GO>(cols),
                          Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete(map_, map_);
  return A;
}

RCP<CrsMatrix> Assembler::stiffness() const {
  return assemble([](const ElementKernel& k, MassKind, const std::vector<Point3>& x,
                     DenseMatrix& Ke) { k.stiffness(x, Ke); });
}

RCP<CrsMatrix> Assembler::mass() const {
  return assemble([](const ElementKernel& k, MassKind m, const std::vector<Point3>& x,
                     DenseMatrix& Me) { k.mass(x, m, Me); });
}

}  // namespace choc
