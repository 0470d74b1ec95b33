#include "contact/SystemGraph.hpp"

#include <algorithm>
#include <utility>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>

namespace choc {
namespace {

// The column map Tpetra would make: the owned ids in the row map's order, then the others
// grouped by owning rank and sorted within each rank.
RCP<const Map> columnMap(const Map& rows, const std::vector<GO>& remote) {
  std::vector<int> owner(remote.size());
  rows.getRemoteIndexList(Teuchos::ArrayView<const GO>(remote), Teuchos::ArrayView<int>(owner));
  std::vector<std::pair<int, GO>> byOwner(remote.size());
  for (size_t k = 0; k < remote.size(); ++k) byOwner[k] = {owner[k], remote[k]};
  std::sort(byOwner.begin(), byOwner.end());
  auto own = rows.getNodeElementList();
  std::vector<GO> gids(own.begin(), own.end());
  for (const auto& p : byOwner) gids.push_back(p.second);
  return rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                     Teuchos::ArrayView<const GO>(gids), 0, rows.getComm()));
}

}  // namespace

SystemGraph buildSystemGraph(const CrsMatrix& K, const CrsMatrix& M, RCP<const Map> map,
                             size_t nLocalDofs, const std::map<LO, std::vector<GO>>& extra) {
  // Every column id this rank's rows reach that another rank owns.
  std::vector<GO> remote;
  for (const CrsMatrix* X : {&K, &M})
    for (GO g : X->getColMap()->getNodeElementList())
      if (!map->isNodeGlobalElement(g)) remote.push_back(g);
  for (const auto& [row, cols] : extra)
    for (GO g : cols)
      if (!map->isNodeGlobalElement(g)) remote.push_back(g);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  RCP<const Map> colMap = columnMap(*map, remote);

  // K's and M's local column indices as the system's.
  auto translate = [&](const CrsMatrix& X) {
    auto xc = X.getColMap();
    std::vector<LO> to(xc->getNodeNumElements());
    for (size_t j = 0; j < to.size(); ++j) to[j] = colMap->getLocalElement(xc->getGlobalElement(LO(j)));
    return to;
  };
  SystemGraph out;
  out.fromK = translate(K);
  out.fromM = translate(M);
  const std::vector<LO>& fromK = out.fromK;
  const std::vector<LO>& fromM = out.fromM;
  const auto Kl = K.getLocalMatrixHost(), Ml = M.getLocalMatrixHost();

  const size_t nRows = map->getNodeNumElements();
  // The arrays are written once, straight into the graph's own views (allocated without being
  // zeroed; the entries' view has room for every K and M entry, the diagonals and the extras,
  // and keeps only what is written: pages never touched cost nothing).
  size_t bound = size_t(Kl.graph.entries.extent(0) + Ml.graph.entries.extent(0)) + nRows;
  for (const auto& [r, cols] : extra) bound += cols.size();
  using RowPtrs = typename CrsGraph::local_graph_device_type::row_map_type::non_const_type;
  using Entries = typename CrsGraph::local_graph_device_type::entries_type::non_const_type;
  RowPtrs rowPtr(Kokkos::ViewAllocateWithoutInitializing("system row pointers"), nRows + 1);
  Entries entries(Kokkos::ViewAllocateWithoutInitializing("system columns"), bound);
  rowPtr(0) = 0;
  size_t nnz = 0;
  // A row of K or M, translated, appended to `row`; `sorted` turns false when the translation
  // breaks its ascending order (a column map ordered differently).
  auto append = [](const auto& X, const std::vector<LO>& from, size_t i, std::vector<LO>& row, bool& sorted) {
    const size_t first = row.size();
    for (auto k = X.graph.row_map(i); k < X.graph.row_map(i + 1); ++k) {
      row.push_back(from[X.graph.entries(k)]);
      if (row.size() > first + 1 && row[row.size() - 2] >= row.back()) sorted = false;
    }
  };
  std::vector<LO> row;
  for (size_t i = 0; i < nRows; ++i) {
    row.clear();
    // K's and M's rows are each ascending when the column maps order alike (the usual case):
    // one merge, not a sort of both (a sort per row cost 0.5 s at 300,000 unknowns).
    bool sorted = true;
    if (i < nLocalDofs) {
      append(Kl, fromK, i, row, sorted);
      const size_t mid = row.size();
      append(Ml, fromM, i, row, sorted);
      if (sorted) std::inplace_merge(row.begin(), row.begin() + long(mid), row.end());
    }
    const LO diagonal = colMap->getLocalElement(map->getGlobalElement(LO(i)));
    auto e = extra.find(LO(i));
    if (sorted && e == extra.end()) {
      const auto at = std::lower_bound(row.begin(), row.end(), diagonal);
      if (at == row.end() || *at != diagonal) row.insert(at, diagonal);
    } else {
      row.push_back(diagonal);
      if (e != extra.end())
        for (GO g : e->second) row.push_back(colMap->getLocalElement(g));
      std::sort(row.begin(), row.end());
    }
    row.erase(std::unique(row.begin(), row.end()), row.end());
    for (LO c : row) entries(nnz++) = c;
    rowPtr(i + 1) = nnz;
  }
  auto graph = rcp(new CrsGraph(map, colMap, rowPtr, Kokkos::subview(entries, std::make_pair(size_t(0), nnz))));
  graph->expertStaticFillComplete(map, map);
  out.graph = graph;
  return out;
}

}  // namespace choc
