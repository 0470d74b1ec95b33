#include "physics/SystemGraph.hpp"

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

// Every column id the system's rows reach (K's, M's, the extras) that another rank owns,
// sorted, once each.
std::vector<GO> remoteColumns(const CrsMatrix& K, const CrsMatrix& M, const Map& map,
                              const std::map<LO, std::vector<GO>>& extra) {
  std::vector<GO> remote;
  for (const CrsMatrix* X : {&K, &M})
    for (GO g : X->getColMap()->getNodeElementList())
      if (!map.isNodeGlobalElement(g)) remote.push_back(g);
  for (const auto& [row, cols] : extra)
    for (GO g : cols)
      if (!map.isNodeGlobalElement(g)) remote.push_back(g);
  std::sort(remote.begin(), remote.end());
  remote.erase(std::unique(remote.begin(), remote.end()), remote.end());
  return remote;
}

// X's local column indices as the system's.
std::vector<LO> translateColumns(const CrsMatrix& X, const Map& colMap) {
  auto xc = X.getColMap();
  std::vector<LO> to(xc->getNodeNumElements());
  for (size_t j = 0; j < to.size(); ++j) to[j] = colMap.getLocalElement(xc->getGlobalElement(LO(j)));
  return to;
}

using LocalMatrix = CrsMatrix::local_matrix_host_type;

// What the system's rows are made of: K's and M's local rows (on the first nLocalDofs rows)
// with their columns translated, every row's diagonal, and the extras.
struct RowSources {
  LocalMatrix Kl, Ml;
  const std::vector<LO>& fromK;
  const std::vector<LO>& fromM;
  size_t nLocalDofs;
  const Map& map;
  const Map& colMap;
  const std::map<LO, std::vector<GO>>& extra;
};

// A row of K or M, translated, appended to `row`; `sorted` turns false when the translation
// breaks its ascending order (a column map ordered differently).
void appendRow(const LocalMatrix& X, const std::vector<LO>& from, size_t i, std::vector<LO>& row, bool& sorted) {
  const size_t first = row.size();
  for (auto k = X.graph.row_map(i); k < X.graph.row_map(i + 1); ++k) {
    row.push_back(from[X.graph.entries(k)]);
    if (row.size() > first + 1 && row[row.size() - 2] >= row.back()) sorted = false;
  }
}

// The system's local row i: its local columns, ascending, once each.
void systemRow(const RowSources& s, size_t i, std::vector<LO>& row) {
  row.clear();
  // K's and M's rows are each ascending when the column maps order alike (the usual case):
  // one merge, not a sort of both (a sort per row cost 0.5 s at 300,000 unknowns).
  bool sorted = true;
  if (i < s.nLocalDofs) {
    appendRow(s.Kl, s.fromK, i, row, sorted);
    const size_t mid = row.size();
    appendRow(s.Ml, s.fromM, i, row, sorted);
    if (sorted) std::inplace_merge(row.begin(), row.begin() + long(mid), row.end());
  }
  const LO diagonal = s.colMap.getLocalElement(s.map.getGlobalElement(LO(i)));
  auto e = s.extra.find(LO(i));
  if (sorted && e == s.extra.end()) {
    const auto at = std::lower_bound(row.begin(), row.end(), diagonal);
    if (at == row.end() || *at != diagonal) row.insert(at, diagonal);
  } else {
    row.push_back(diagonal);
    if (e != s.extra.end())
      for (GO g : e->second) row.push_back(s.colMap.getLocalElement(g));
    std::sort(row.begin(), row.end());
  }
  row.erase(std::unique(row.begin(), row.end()), row.end());
}

// The graph of the system's rows on map, with the column map colMap.
RCP<const CrsGraph> graphOf(const RowSources& s, RCP<const Map> map, RCP<const Map> colMap) {
  const size_t nRows = map->getNodeNumElements();
  // The arrays are written once, straight into the graph's own views (allocated without being
  // zeroed; the entries' view has room for every K and M entry, the diagonals and the extras,
  // and keeps only what is written: pages never touched cost nothing).
  size_t bound = size_t(s.Kl.graph.entries.extent(0) + s.Ml.graph.entries.extent(0)) + nRows;
  for (const auto& [r, cols] : s.extra) bound += cols.size();
  using RowPtrs = typename CrsGraph::local_graph_device_type::row_map_type::non_const_type;
  using Entries = typename CrsGraph::local_graph_device_type::entries_type::non_const_type;
  RowPtrs rowPtr(Kokkos::ViewAllocateWithoutInitializing("system row pointers"), nRows + 1);
  Entries entries(Kokkos::ViewAllocateWithoutInitializing("system columns"), bound);
  rowPtr(0) = 0;
  size_t nnz = 0;
  std::vector<LO> row;
  for (size_t i = 0; i < nRows; ++i) {
    systemRow(s, i, row);
    for (LO c : row) entries(nnz++) = c;
    rowPtr(i + 1) = nnz;
  }
  auto graph = rcp(new CrsGraph(map, colMap, rowPtr, Kokkos::subview(entries, std::make_pair(size_t(0), nnz))));
  graph->expertStaticFillComplete(map, map);
  return graph;
}

}  // namespace

SystemGraph buildSystemGraph(const CrsMatrix& K, const CrsMatrix& M, RCP<const Map> map,
                             size_t nLocalDofs, const std::map<LO, std::vector<GO>>& extra) {
  RCP<const Map> colMap = columnMap(*map, remoteColumns(K, M, *map, extra));
  // K's and M's local column indices as the system's.
  SystemGraph out;
  out.fromK = translateColumns(K, *colMap);
  out.fromM = translateColumns(M, *colMap);
  const RowSources rows{K.getLocalMatrixHost(), M.getLocalMatrixHost(), out.fromK, out.fromM, nLocalDofs,
                        *map, *colMap, extra};
  out.graph = graphOf(rows, map, colMap);
  return out;
}

}  // namespace choc
