// ContactManager::forwardIncrement: exact contact for explicit central differences.
#include <algorithm>
#include <cmath>

#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

void ContactManager::forwardIncrement(const Vector& uStar, const Vector& inverseMass, double h2,
                                      Vector& a) {
  const std::vector<double> g = gaps(uStar);
  if (inverseMassTopology_ != topologyVersion_) {  // 1/m of each contact DOF (constant mass)
    inverseMassAtContact_ = gather(contactDofs_, inverseMass);
    inverseMassTopology_ = topologyVersion_;
  }
  const std::vector<double>& w = inverseMassAtContact_;
  const size_t nS = constraints_.size();
  std::vector<double> lam(nS, 0.0), diag(nS, 0.0), shift(contactDofs_.size(), 0.0);
  double scale = 0.0;
  for (size_t s = 0; s < nS; ++s) {
    for (const auto& [k, c] : localTerms_[s]) diag[s] += h2 * c * c * w[k];
    scale = std::max(scale, std::abs(g[s]));
  }
  const double tol = 1e-12 * scale;
  const int maxSweeps = 1000;
  int sweep = 0;
  for (; sweep < maxSweeps; ++sweep) {
    double change = 0.0;  // largest change of a gap in this sweep [m]
    for (size_t s = 0; s < nS; ++s) {
      if (!(diag[s] > 0)) continue;
      double r = g[s];
      for (const auto& [k, c] : localTerms_[s]) r += c * shift[k];
      const double next = std::max(0.0, lam[s] - r / diag[s]);
      const double d = next - lam[s];
      if (d == 0.0) continue;
      for (const auto& [k, c] : localTerms_[s]) shift[k] += h2 * w[k] * c * d;
      lam[s] = next;
      change = std::max(change, std::abs(d) * diag[s]);
    }
    if (change <= tol) break;
  }
  if (sweep == maxSweeps)
    throw NumericalError(format("forward-increment contact: the pressures did not converge in %d "
                                "sweeps (%s)", maxSweeps, activeSummary().c_str()));
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
}

}  // namespace choc
