// The two strategies that take the multipliers out of the Newton system: condensed node by node
// (contact/ContactCondensation.hpp) and projected (contact/ContactProjection.hpp).
#include "contact/ContactCondensation.hpp"
#include "contact/ContactProjection.hpp"
#include "contact/ContactStrategies.hpp"

namespace choc {

CondensedStrategy::CondensedStrategy(ContactManager& geometry) : ContactStrategy(geometry) {}
CondensedStrategy::~CondensedStrategy() = default;

void CondensedStrategy::attach(const RCP<const Map>& /*dofMap*/) {
  condensation_ = std::make_unique<ContactCondensation>(geometry_);
}
void CondensedStrategy::eliminate(const RCP<CrsMatrix>& W, std::vector<MatrixEntry> columns, GO nU) {
  condensation_->project(W, columns, nU);  // every row was rewritten before
}
void CondensedStrategy::rightHandSide(const CrsMatrix& /*W*/, const Vector& r, const Vector& u, MultiVector& b) {
  condensation_->rightHandSide(r, u, b);
}
void CondensedStrategy::takeSolution(const CrsMatrix& /*W*/, const MultiVector& x, Vector& du) {
  condensation_->takeSolution(x, du);
}

void ProjectedStrategy::attach(const RCP<const Map>& dofMap) {
  projection_ = std::make_shared<ContactProjection>(geometry_, dofMap);
}
void ProjectedStrategy::eliminate(const RCP<CrsMatrix>& /*W*/, std::vector<MatrixEntry> columns, GO nU) {
  projection_->setMultiplierColumns(std::move(columns), nU);
}
// Without friction W holds no contact term: its factorisation and preconditioner outlive every
// change of status.
std::vector<char> ProjectedStrategy::statusKey() const {
  if (!geometry_.hasFriction()) return {};
  return ContactStrategy::statusKey();
}
void ProjectedStrategy::rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) {
  projection_->rightHandSide(W, r, u, b);
}
void ProjectedStrategy::takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) {
  projection_->takeSolution(W, x, du);
}
std::shared_ptr<const ConstraintProjector> ProjectedStrategy::projection() const { return projection_; }

}  // namespace choc
