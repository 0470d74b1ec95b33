#include "physics/StateLoad.hpp"

#include <stdexcept>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/DofMap.hpp"
#include "physics/Loads.hpp"

namespace choc {

StateLoad::StateLoad(std::string name, double rampTime, const DofMap& dofs, int components, const CrsMatrix& K)
    : name_(std::move(name)), rampTime_(rampTime), dofs_(dofs), components_(components), rowMap_(K.getRowMap()),
      colMap_(K.getColMap()), importer_(K.getGraph()->getImporter()) {
  if (!importer_.is_null()) uCol_ = rcp(new Vector(colMap_));
}

void StateLoad::addGroup(const std::vector<int>& nodes, std::vector<Point3> X, size_t index) {
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  Group g{std::move(X), {}, {}, index};
  bool mine = false;
  for (int node : nodes)
    for (int c = 0; c < 3; ++c) {
      const long long d = c < components_ ? dofs_.dof(node, c) : -1;
      LO col = d < 0 ? LO(-1) : colMap_->getLocalElement(GO(d));
      LO row = d < 0 ? LO(-1) : rowMap_->getLocalElement(GO(d));
      if (col == invalid) col = -1;
      if (row == invalid) row = -1;
      g.col.push_back(col);
      g.row.push_back(row);
      mine = mine || row >= 0;
    }
  if (mine) groups_.push_back(std::move(g));  // a group with a row here: all its DOFs are columns
}

double StateLoad::factor(double t) const { return rampFactor(rampTime_, t); }

template <class Visit>
void StateLoad::forEachGroup(const Teuchos::ArrayRCP<const double>& uCol, bool withTangent, Visit&& visit) const {
  std::vector<Point3> x;
  std::vector<double> f;
  DenseMatrix Kf;
  for (const Group& g : groups_) {
    x = g.X;
    for (size_t a = 0; a < x.size(); ++a)
      for (int c = 0; c < 3; ++c)
        if (g.col[3 * a + size_t(c)] >= 0) x[a][size_t(c)] += uCol[g.col[3 * a + size_t(c)]];
    groupForce(g, x, f, withTangent ? &Kf : nullptr);
    visit(g, f, Kf);
  }
}

void StateLoad::subtractForce(const Teuchos::ArrayRCP<const double>& uCol, double t,
                              Teuchos::ArrayRCP<double>& out) const {
  const double lambda = factor(t);
  if (lambda == 0.0) return;
  forEachGroup(uCol, false, [&](const Group& g, const std::vector<double>& f, const DenseMatrix&) {
    for (size_t k = 0; k < g.row.size(); ++k)
      if (g.row[k] >= 0) out[g.row[k]] -= lambda * f[k];
  });
}

void StateLoad::addTangent(const Teuchos::ArrayRCP<const double>& uCol, double t, CrsMatrix& K) const {
  const double lambda = factor(t);
  if (lambda == 0.0) return;
  std::vector<LO> cols;
  std::vector<double> vals;
  forEachGroup(uCol, true, [&](const Group& g, const std::vector<double>&, const DenseMatrix& Kf) {
    for (size_t i = 0; i < g.row.size(); ++i) {
      if (g.row[i] < 0) continue;
      cols.clear();
      vals.clear();
      for (size_t j = 0; j < g.col.size(); ++j)
        if (g.col[j] >= 0) cols.push_back(g.col[j]), vals.push_back(-lambda * Kf(int(i), int(j)));
      const LO found = K.sumIntoLocalValues(g.row[i], Teuchos::ArrayView<const LO>(cols), Teuchos::ArrayView<const double>(vals));
      if (size_t(found) != cols.size())  // faces of finite-strain blocks (full patterns), couplings in the graph
        throw std::logic_error("load '" + name_ + "': load stiffness entries outside the stiffness' graph");
    }
  });
}

void StateLoad::addForce(const Vector& u, double t, Vector& out) const {
  const double lambda = factor(t);
  if (lambda == 0.0) return;
  const Vector* onCols = &u;
  if (!importer_.is_null()) {
    uCol_->doImport(u, *importer_, Tpetra::INSERT);
    onCols = uCol_.get();
  }
  auto o = out.getDataNonConst();
  forEachGroup(onCols->getData(), false, [&](const Group& g, const std::vector<double>& f, const DenseMatrix&) {
    for (size_t k = 0; k < g.row.size(); ++k)
      if (g.row[k] >= 0) o[g.row[k]] += lambda * f[k];
  });
}

}  // namespace choc
