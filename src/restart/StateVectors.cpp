#include "restart/StateVectors.hpp"

#include <Tpetra_Vector.hpp>

#include "fem/FieldGather.hpp"

namespace choc {

StateVectors::StateVectors(const DofMap& dofs) : dofs_(dofs) {
  for (int n = 0; n < dofs.numNodes(); ++n)
    for (int c = 0; c < 8; ++c)
      if (dofs.isFree(n, c)) canonicalDof_.push_back(dofs.dof(n, c));
}

void StateVectors::put(StateArchive& a, const std::string& name, const Vector& v) const {
  const std::vector<double> g = gatherAll(v, 0, dofs_);
  std::vector<double> c(canonicalDof_.size());
  for (size_t i = 0; i < c.size(); ++i) c[i] = g[static_cast<size_t>(canonicalDof_[i])];
  a.putVector(name, c);
}

void StateVectors::get(const StateArchive& a, const std::string& name, Vector& v) const {
  const std::vector<double> c = a.getVector<double>(name, canonicalDof_.size());
  auto map = v.getMap();
  auto data = v.getDataNonConst();
  for (size_t i = 0; i < c.size(); ++i) {
    const LO l = map->getLocalElement(GO(canonicalDof_[i]));
    if (l != Teuchos::OrdinalTraits<LO>::invalid()) data[l] = c[i];
  }
}

}  // namespace choc
