// The velocity update of Laursen and Love (2002), after an accepted implicit step: the contact
// treatment that keeps the bodies' own mass (contact/ContactStrategy.hpp, correctVelocity).
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactStrategy.hpp"
#include "contact/ForwardIncrementSolver.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {

// x += W B_A^T lambda with B_A x = target on the active constraints (lambda of either sign:
// Gauss-Seidel on B W B^T), on the rows this rank owns.
void project(const ContactManager& g, const std::vector<int>& active, const std::vector<double>& rates,
             const std::vector<double>& w, const Vector& inverseMass, Vector& x, const char* what) {
  std::vector<std::vector<std::pair<int, double>>> terms;
  std::vector<double> r;
  for (int s : active) {
    terms.push_back(g.localTerms()[size_t(s)]);
    r.push_back(rates[size_t(s)]);
  }
  const ForwardIncrementResult fi = solveForwardIncrement(terms, r, w, 1.0, 1000, false);
  if (!fi.converged)
    throw NumericalError(format("contact velocity update: the %s impulses did not converge in %d sweeps (%s)", what,
                                fi.sweeps, g.activeSummary().c_str()));
  auto xd = x.getDataNonConst();
  auto wd = inverseMass.getData();
  const Map& map = *x.getMap();
  for (size_t k = 0; k < active.size(); ++k) {
    if (fi.lambda[k] == 0.0) continue;
    for (const auto& [dof, c] : g.constraints()[size_t(active[k])].terms) {
      const LO l = map.getLocalElement(dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) xd[l] += wd[l] * c * fi.lambda[k];
    }
  }
}

}  // namespace

// Every constraint active at the end of the step keeps its surface: its gap rate and gap
// acceleration are brought to 0 (the obstacles move at constant velocity) by the lumped-mass
// projection, v and a moved only along the constraints' rows.
bool ContactStrategy::correctVelocity(Vector& v, Vector& a, const Vector& inverseMass) {
  const ContactManager& g = geometry_;
  const ContactActiveSet& set = g.activeSet();
  std::vector<int> active;
  for (int s = 0; s < g.numConstraints(); ++s)
    if (set.status[size_t(s)]) active.push_back(s);
  if (active.empty()) return false;
  if (inverseMassTopology_ != g.topologyVersion()) {
    inverseMassAtContact_ = g.contactValues(inverseMass);
    inverseMassTopology_ = g.topologyVersion();
  }
  project(g, active, g.gapRates(v), inverseMassAtContact_, inverseMass, v, "velocity");
  const std::vector<double> x = g.contactValues(a);
  std::vector<double> accelerations(size_t(g.numConstraints()), 0.0);
  for (int s : active)
    for (const auto& [k, c] : g.localTerms()[size_t(s)]) accelerations[size_t(s)] += c * x[size_t(k)];
  project(g, active, accelerations, inverseMassAtContact_, inverseMass, a, "acceleration");
  return true;
}

}  // namespace choc
