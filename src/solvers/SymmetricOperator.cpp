#include "solvers/SymmetricOperator.hpp"

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

SymmetricOperator::SymmetricOperator(RCP<const CrsMatrix> A, std::unique_ptr<SymmetricProduct> product)
    : A_(std::move(A)), product_(std::move(product)) {}

RCP<SymmetricOperator> SymmetricOperator::build(RCP<const CrsMatrix> A) {
  if (A->getGlobalNumRows() < Tpetra::global_size_t(SymmetricProduct::kWorthwhileRows)) return Teuchos::null;
  auto product = SymmetricProduct::build(*A);
  if (!product) return Teuchos::null;
  return rcp(new SymmetricOperator(A, std::move(product)));
}

bool SymmetricOperator::refill(RCP<const CrsMatrix> A) {
  if (!product_->refill(*A)) return false;
  A_ = A;
  return true;
}

void SymmetricOperator::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, double alpha,
                              double beta) const {
  for (size_t c = 0; c < X.getNumVectors(); ++c) {
    auto x = X.getVector(c);
    auto y = Y.getVectorNonConst(c);
    if (alpha == 1.0 && beta == 0.0) {
      product_->apply(*x, *y);
      continue;
    }
    if (tmp_.is_null()) tmp_ = rcp(new Vector(A_->getRangeMap()));
    product_->apply(*x, *tmp_);
    y->update(alpha, *tmp_, beta);  // beta = 0 ignores Y's old values (NaN included)
  }
}

}  // namespace choc
