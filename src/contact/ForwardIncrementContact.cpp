// ContactManager::forwardIncrement: exact contact for explicit central differences (the
// pressures: contact/ForwardIncrementSolver.hpp; the statuses and accelerations here).
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "contact/ForwardIncrementSolver.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

void ContactManager::forwardIncrement(const Vector& u, const Vector& uStar, const Vector& inverseMass, double h,
                                      double h2, Vector& a) {
  const std::vector<double> xStar = contactValues(uStar);
  const std::vector<double> g = gapsAt(xStar);
  if (inverseMassTopology_ != topologyVersion_) {  // 1/m of each contact DOF (constant mass)
    inverseMassAtContact_ = gather(contactDofs_, inverseMass);
    inverseMassTopology_ = topologyVersion_;
  }
  const size_t nS = constraints_.size();
  const ForwardIncrementResult fi = solveForwardIncrement(localTerms_, g, inverseMassAtContact_, h2);
  if (!fi.converged)
    throw NumericalError(format("forward-increment contact: the pressures did not converge in %d "
                                "sweeps (%s)", fi.sweeps, activeSummary().c_str()));
  const std::vector<double>& lam = fi.lambda;
  bool changed = false;
  for (size_t s = 0; s < nS; ++s) {
    const char active = lam[s] > 0.0;
    changed = changed || active != set_.status[s];
    set_.status[s] = active;
    set_.lambda[s] = lam[s];
  }
  if (changed) ++set_.version;
  auto ad = a.getDataNonConst();
  auto wd = inverseMass.getData();
  for (size_t s = 0; s < nS; ++s) {
    if (lam[s] == 0.0) continue;
    for (const auto& [dof, c] : constraints_[s].terms) {
      const LO l = map_->getLocalElement(dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) ad[l] += wd[l] * c * lam[s];
    }
  }
  if (!friction_) return;
  // The predicted positions with the pressures' motion (along each constraint's normal; it
  // moves another constraint sharing a master node tangentially).
  std::vector<double> corrected = xStar;
  for (size_t s = 0; s < nS; ++s)
    for (const auto& [k, c] : localTerms_[s]) corrected[k] += h2 * inverseMassAtContact_[k] * c * lam[s];
  friction_->increment(contactValues(u), corrected, h, h2, inverseMassAtContact_, inverseMass, a,
                       [&] { return activeSummary(); });
}

}  // namespace choc
