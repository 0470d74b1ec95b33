#include <Tpetra_MultiVector.hpp>

#include "solvers/ConstraintProjector.hpp"

namespace choc {

ProjectedOperator::ProjectedOperator(RCP<const Operator> inner, RCP<const Map> map,
                                     const ConstraintProjector& projector, bool inverseScale)
    : inner_(std::move(inner)), map_(std::move(map)), projector_(projector), inverseScale_(inverseScale) {}

void ProjectedOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp /*mode*/, double alpha,
                              double beta) const {
  const size_t nv = X.getNumVectors();
  if (px_.is_null() || px_->getNumVectors() != nv) {  // allocated once: a product a Krylov iteration
    px_ = rcp(new MultiVector(map_, nv, false));
    bpx_ = rcp(new MultiVector(map_, nv, false));
    out_ = rcp(new MultiVector(map_, nv, false));
  }
  MultiVector &px = *px_, &bpx = *bpx_, &out = *out_;
  projector_.project(X, px);  // P X
  if (inner_.is_null()) bpx.assign(px);
  else inner_->apply(px, bpx);
  if (inverseScale_) projector_.project(bpx, out);  // P M P X
  else projector_.projectRows(bpx, out);            // P_L A P X
  const double c = inverseScale_ ? 1.0 / projector_.scale() : projector_.scale();
  out.update(c, X, -c, px, 1.0);  // + c (X - P X)
  Y.update(alpha, out, beta);
}

}  // namespace choc
