// A symmetric CRS matrix as the Tpetra operator a Krylov solver multiplies by, its products
// from half its entries (fem/SymmetricProduct: the diagonal and upper triangle of each rank's
// block): a CG iteration on a mass-dominated matrix is about one such product, bounded by
// memory traffic. The matrix itself stays the preconditioner's and the residual check's.
#pragma once
#include <memory>

#include "core/TpetraTypes.hpp"
#include "fem/SymmetricProduct.hpp"

namespace choc {

class SymmetricOperator : public Operator {
 public:
  // Null unless A is symmetric within round-off (SymmetricProduct::build) and has at least
  // SymmetricProduct::kWorthwhileRows rows. Collective.
  static RCP<SymmetricOperator> build(RCP<const CrsMatrix> A);
  // A's new values on the same graph (SymmetricProduct::refill); false, on every rank, when the
  // product no longer stands for A. Collective.
  bool refill(RCP<const CrsMatrix> A);

  RCP<const Map> getDomainMap() const override { return A_->getDomainMap(); }
  RCP<const Map> getRangeMap() const override { return A_->getRangeMap(); }
  // Y = alpha A X + beta Y (A symmetric: the transposes are A).
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;
  bool hasTransposeApply() const override { return true; }

 private:
  SymmetricOperator(RCP<const CrsMatrix> A, std::unique_ptr<SymmetricProduct> product);
  RCP<const CrsMatrix> A_;
  std::unique_ptr<SymmetricProduct> product_;
  mutable RCP<Vector> tmp_;  // A x when alpha != 1 or beta != 0
};

}  // namespace choc
