#include "physics/LinearElasticForce.hpp"

#include <cmath>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

LinearElasticForce::LinearElasticForce(RCP<const CrsMatrix> K)
    : K_(std::move(K)), tmp_(rcp(new Vector(K_->getRowMap()))), colTmp_(rcp(new Vector(K_->getColMap()))) {}

void LinearElasticForce::preferSymmetricProducts() {
  if (!symmetricK_ && K_->getGlobalNumRows() >= SymmetricProduct::kWorthwhileRows)
    symmetricK_ = SymmetricProduct::build(*K_);
}

void LinearElasticForce::apply(const Vector& x, Vector& out) const {
  if (symmetricK_) symmetricK_->apply(x, out);
  else K_->apply(x, out);
}

double LinearElasticForce::strainEnergy(const Vector& u, const Vector* internalForceAtU) const {
  if (internalForceAtU) return 0.5 * u.dot(*internalForceAtU);
  apply(u, *tmp_);
  return 0.5 * u.dot(*tmp_);
}

double LinearElasticForce::termsNorm(const Vector& u) const {
  Vector& uc = *colTmp_;
  auto importer = K_->getGraph()->getImporter();
  if (importer.is_null()) uc.assign(u);
  else uc.doImport(u, *importer, Tpetra::INSERT);
  auto udata = uc.getData();
  const double* ud = udata.getRawPtr();
  // The local CRS arrays directly, through raw pointers (a row view per row costs more than
  // the row's arithmetic; the views' accessors in the inner loop cost twice the raw loop).
  const auto A = K_->getLocalMatrixHost();
  const size_t nRows = size_t(A.graph.row_map.extent(0)) - 1;
  const auto* rows = A.graph.row_map.data();
  const LO* cols = A.graph.entries.data();
  const double* vals = A.values.data();
  // Four partial sums per row: one running sum waits on each addition's latency (3 times
  // the time of a product with K).
  double local = 0.0;
  for (size_t i = 0; i < nRows; ++i) {
    double part[4] = {0.0, 0.0, 0.0, 0.0};
    auto k = rows[i];
    const auto end = rows[i + 1];
    for (; k + 4 <= end; k += 4)
      for (int j = 0; j < 4; ++j) part[j] += std::abs(vals[k + j]) * std::abs(ud[cols[k + j]]);
    for (; k < end; ++k) part[0] += std::abs(vals[k]) * std::abs(ud[cols[k]]);
    const double row = (part[0] + part[1]) + (part[2] + part[3]);
    local += row * row;
  }
  double global = 0.0;
  Teuchos::reduceAll<int, double>(*K_->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return std::sqrt(global);
}

}  // namespace choc
