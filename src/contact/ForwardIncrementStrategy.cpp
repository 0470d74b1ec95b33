// Exact contact for explicit central differences by forward increments (the pressures:
// contact/ForwardIncrementSolver.hpp; the statuses and accelerations here): the pressures
// lambda >= 0 for which the predicted positions uStar + h2 M^-1 B^T lambda have no negative gap,
// lambda_s = 0 where the gap is open; then, with friction, each active node's tangential force that
// stops its relative tangential motion from u to uStar, capped at mu lambda
// (CoulombFriction::increment), h the sub-step. A rigid body's contact DOFs (inverse mass 0)
// move with their body: the pressures see its inverse mass and inertia (ContactBodies), and the
// body gathers their forces from r.
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactStrategies.hpp"
#include "contact/ForwardIncrementSolver.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

// The friction of an explicit run is decided by the increments, not by the implicit law.
ForwardIncrementStrategy::ForwardIncrementStrategy(ContactManager& geometry) : ContactStrategy(geometry) {
  if (geometry_.hasFriction()) geometry_.friction()->useForwardIncrements(true);
}

void ForwardIncrementStrategy::addExplicitIncrement(const Vector& u, const Vector& uStar, const Vector& inverseMass,
                                                    double h, double h2, Vector& a, Vector& r) {
  const std::vector<double> xStar = geometry_.contactValues(uStar);
  const std::vector<double> g = geometry_.gapsAt(xStar);
  if (inverseMassTopology_ != geometry_.topologyVersion()) {  // 1/m of each contact DOF (constant mass)
    inverseMassAtContact_ = geometry_.contactValues(inverseMass);
    inverseMassTopology_ = geometry_.topologyVersion();
  }
  const auto& constraints = geometry_.constraints();
  const auto& localTerms = geometry_.localTerms();
  const size_t nS = constraints.size();
  const RigidContactBodies rigid = bodies_ ? bodies_->describe(geometry_.contactDofs()) : RigidContactBodies();
  const ForwardIncrementResult fi =
      solveForwardIncrement(localTerms, g, inverseMassAtContact_, h2, 1000, true, bodies_ ? &rigid : nullptr);
  if (!fi.converged)
    throw NumericalError(format("forward-increment contact: the pressures did not converge in %d "
                                "sweeps (%s)", fi.sweeps, geometry_.activeSummary().c_str()));
  const std::vector<double>& lam = fi.lambda;
  ContactActiveSet& set = geometry_.activeSet();
  bool changed = false;
  for (size_t s = 0; s < nS; ++s) {
    const char active = lam[s] > 0.0;
    changed = changed || active != set.status[s];
    set.status[s] = active;
    set.lambda[s] = lam[s];
  }
  if (changed) ++set.version;
  auto ad = a.getDataNonConst(), rd = r.getDataNonConst();
  auto wd = inverseMass.getData();
  const Map& map = *inverseMass.getMap();
  for (size_t s = 0; s < nS; ++s) {
    if (lam[s] == 0.0) continue;
    for (const auto& [dof, c] : constraints[s].terms) {
      const LO l = map.getLocalElement(dof);
      if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      ad[l] += wd[l] * c * lam[s];
      rd[l] -= c * lam[s];
    }
  }
  if (!geometry_.hasFriction()) return;
  // The predicted positions with the pressures' motion (along each constraint's normal; it
  // moves another constraint sharing a master node tangentially).
  std::vector<double> corrected = xStar;
  for (size_t s = 0; s < nS; ++s)
    for (const auto& [k, c] : localTerms[s]) corrected[k] += h2 * inverseMassAtContact_[k] * c * lam[s];
  geometry_.friction()->increment(geometry_.contactValues(u), corrected, h, h2, inverseMassAtContact_, inverseMass, a,
                                  [&] { return geometry_.activeSummary(); });
}

}  // namespace choc
