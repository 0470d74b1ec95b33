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
  Teuchos::ArrayRCP<size_t> rowPtr(nRows + 1, 0);
  std::vector<LO> cols;
  cols.reserve(size_t(Kl.graph.entries.extent(0)) + nRows);
  std::vector<LO> row;
  for (size_t i = 0; i < nRows; ++i) {
    row.clear();
    if (i < nLocalDofs) {
      for (auto k = Kl.graph.row_map(i); k < Kl.graph.row_map(i + 1); ++k) row.push_back(fromK[Kl.graph.entries(k)]);
      for (auto k = Ml.graph.row_map(i); k < Ml.graph.row_map(i + 1); ++k) row.push_back(fromM[Ml.graph.entries(k)]);
    }
    row.push_back(colMap->getLocalElement(map->getGlobalElement(LO(i))));
    auto e = extra.find(LO(i));
    if (e != extra.end())
      for (GO g : e->second) row.push_back(colMap->getLocalElement(g));
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    cols.insert(cols.end(), row.begin(), row.end());
    rowPtr[i + 1] = cols.size();
  }
  Teuchos::ArrayRCP<LO> colInd(cols.size());
  std::copy(cols.begin(), cols.end(), colInd.begin());
  std::vector<LO>().swap(cols);
  auto graph = rcp(new CrsGraph(map, colMap, rowPtr, colInd));
  graph->expertStaticFillComplete(map, map);
  out.graph = graph;
  return out;
}

}  // namespace choc
