// The rotation onto the contact nodes' massless directions (physics/MasslessBasis.hpp).
#include "physics/MasslessBasis.hpp"

#include "fem/MatrixOps.hpp"

#include <cmath>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <TpetraExt_MatrixMatrix.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

namespace {

// The node's frame over its free components: the directions, then the axes' remainders
// (Gram-Schmidt), each restricted to the free components' coordinates.
std::vector<std::vector<double>> nodeFrame(const std::vector<Point3>& dirs, const std::vector<int>& freeComps) {
  const size_t nf = freeComps.size();
  std::vector<std::vector<double>> frame;
  auto add = [&](std::vector<double> v) {
    for (const auto& f : frame) {
      double p = 0.0;
      for (size_t i = 0; i < nf; ++i) p += f[i] * v[i];
      for (size_t i = 0; i < nf; ++i) v[i] -= p * f[i];
    }
    double n = 0.0;
    for (double x : v) n += x * x;
    n = std::sqrt(n);
    if (!(n > 0.5) || frame.size() == nf) return;
    for (double& x : v) x /= n;
    frame.push_back(v);
  };
  for (const Point3& d : dirs) {
    std::vector<double> v(nf);
    for (size_t i = 0; i < nf; ++i) v[i] = d[size_t(freeComps[i])];
    add(v);
  }
  for (size_t a = 0; a < nf; ++a) {
    std::vector<double> v(nf, 0.0);
    v[a] = 1.0;
    add(v);
  }
  if (frame.size() != nf) throw std::logic_error("massless basis: a node's frame is incomplete");
  return frame;
}

}  // namespace

MasslessBasis masslessBasis(const std::vector<std::vector<Point3>>& directions, const DofMap& dofs,
                            const RCP<const Map>& map) {
  MasslessBasis b;
  b.mask.assign(map->getNodeNumElements(), 0);
  RCP<CrsMatrix> Q = rcp(new CrsMatrix(map, 3));
  long long mine = 0;
  for (int node = 0; node < dofs.numNodes(); ++node) {
    if (!dofs.ownsNode(node)) continue;
    std::vector<int> freeComps;
    for (int c = 0; c < 3; ++c)
      if (dofs.dof(node, c) >= 0) freeComps.push_back(c);
    const std::vector<std::vector<double>> frame = nodeFrame(directions[size_t(node)], freeComps);
    const size_t massless = std::min(directions[size_t(node)].size(), frame.size());
    for (size_t i = 0; i < freeComps.size(); ++i) {
      std::vector<GO> cols;
      std::vector<double> vals;
      for (size_t j = 0; j < frame.size(); ++j) {
        cols.push_back(GO(dofs.dof(node, freeComps[j])));
        vals.push_back(frame[j][i]);
      }
      Q->insertGlobalValues(GO(dofs.dof(node, freeComps[i])), Teuchos::ArrayView<const GO>(cols),
                            Teuchos::ArrayView<const double>(vals));
    }
    for (size_t j = 0; j < massless; ++j) {
      b.mask[size_t(map->getLocalElement(GO(dofs.dof(node, freeComps[j]))))] = 1;
      ++mine;
    }
  }
  Q->fillComplete(map, map);
  b.rotation = Q;
  Teuchos::reduceAll<int, long long>(*map->getComm(), Teuchos::REDUCE_SUM, mine, Teuchos::outArg(b.global));
  return b;
}

RCP<CrsMatrix> rotatedMatrix(const CrsMatrix& Q, const CrsMatrix& A) {
  CrsMatrix QtA(Q.getDomainMap(), 0);
  Tpetra::MatrixMatrix::Multiply(Q, true, A, false, QtA);
  RCP<CrsMatrix> out = rcp(new CrsMatrix(Q.getDomainMap(), 0));
  Tpetra::MatrixMatrix::Multiply(QtA, false, Q, false, *out);
  return out;
}

void zeroMasslessEntries(CrsMatrix& A, const std::vector<char>& mask) {
  auto rowMap = A.getRowMap();
  Vector rowFlag(rowMap), colFlag(A.getColMap());
  {
    auto f = rowFlag.getDataNonConst();
    for (size_t i = 0; i < mask.size(); ++i) f[i] = mask[i] ? 1.0 : 0.0;
  }
  colFlag.doImport(rowFlag, Tpetra::Import<LO, GO>(rowMap, A.getColMap()), Tpetra::INSERT);
  auto cf = colFlag.getData();
  auto colMap = A.getColMap();
  A.resumeFill();
  RowCopy row;
  for (size_t i = 0; i < mask.size(); ++i) {
    const GO g = rowMap->getGlobalElement(LO(i));
    row.read(A, g);
    bool changed = false;
    for (size_t k = 0; k < row.size; ++k)
      if ((mask[i] || cf[colMap->getLocalElement(row.cols[k])] != 0.0) && row.vals[k] != 0.0) {
        row.vals[k] = 0.0;
        changed = true;
      }
    if (changed) A.replaceGlobalValues(g, row.cols(0, row.size), row.vals(0, row.size));
  }
  A.fillComplete(A.getDomainMap(), A.getRangeMap());
}

void rotate(const CrsMatrix& Q, const Vector& x, Vector& out, bool toRotated) {
  Q.apply(x, out, toRotated ? Teuchos::TRANS : Teuchos::NO_TRANS);
}

}  // namespace choc
