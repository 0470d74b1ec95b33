// Linear equality constraints C^T x = t eliminated from a Krylov solve by an orthogonal
// projector P = I - C (C^T C)^-1 C^T onto their null space. The solver multiplies by
//     A_P = P_L A P + sigma (I - P)      and preconditions with     P M^-1 P + (I - P) / sigma,
// where M^-1 is the preconditioner of A itself (built from A, so a change of constraints keeps
// it). P_L, the rows' projector, is P unless the multipliers' columns V differ from C (friction:
// P_L = I - V (C^T V)^-1 C^T, which annihilates V; range(P_L) is still null(C^T)). With P_L = P
// both are symmetric positive definite when A and M^-1 are on the null space, so CG applies.
// The caller writes its right-hand side in range(P) and adds the constrained part of the
// solution itself (contact/ContactProjection.hpp).
#pragma once
#include "core/TpetraTypes.hpp"

namespace choc {

class ConstraintProjector {
 public:
  virtual ~ConstraintProjector() = default;
  // Y = P X (collective; X and Y on the solver's map, may not alias).
  virtual void project(const MultiVector& X, MultiVector& Y) const = 0;
  // Y = P_L X (collective).
  virtual void projectRows(const MultiVector& X, MultiVector& Y) const { project(X, Y); }
  // sigma: the scale of A (its largest diagonal entry), so that A_P is as well conditioned as A.
  virtual double scale() const = 0;
};

// Y = alpha (P_L B P X + c (X - P X)) + beta Y with B an operator (null: the identity): the
// system's operator (c = sigma), or with P for P_L the preconditioner (c = 1 / sigma).
class ProjectedOperator : public Operator {
 public:
  ProjectedOperator(RCP<const Operator> inner, RCP<const Map> map, const ConstraintProjector& projector,
                    bool inverseScale);
  RCP<const Map> getDomainMap() const override { return map_; }
  RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;
  bool hasTransposeApply() const override { return false; }

 private:
  RCP<const Operator> inner_;
  RCP<const Map> map_;
  const ConstraintProjector& projector_;
  bool inverseScale_;  // c = 1 / sigma (a preconditioner), else sigma
  mutable RCP<MultiVector> px_, bpx_, out_;  // work vectors, kept between products
};

}  // namespace choc
