#include "analysis/ExplicitPlan.hpp"

#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "timeint/TimeGrid.hpp"

namespace choc {

ExplicitPlan planExplicit(const ExplicitInputs& in) {
  ExplicitPlan p;
  RCP<Vector> m = lumpedMassDiagonal(in.M);
  if (m.is_null())
    throwInput(in.file, in.analysisPath + "/Scheme", "central differences",
               "needs a diagonal mass with every entry positive",
               "set 'Mass' = 'lumped' in every block of Model/Blocks and 'Contact Mass' = 'standard'");
  p.massDiagonal = m;
  p.inverseMass = rcp(new Vector(m->getMap()));
  p.inverseMass->reciprocal(*m);
  const double k = in.contact ? in.contact->springStiffness() : 0.0;
  p.bound = omegaMaxBound(in.K, *m, in.contact ? &in.contact->geometry() : nullptr, k, in.links, in.meshBound);
  const double w = p.bound.omegaMax;
  const double xi = w > 0 ? 0.5 * (in.rayleighK * w + in.rayleighM / w) : 0.0;
  p.criticalStep = explicitCriticalStep(w, xi);
  // Penalty contact and links switch on and off (timeint/StabilityPolicy.hpp).
  const Switching switching = k > 0 ? Switching::PenaltyContact
                              : in.links ? Switching::PenaltyLinks
                                         : Switching::None;
  p.switching = switching;
  p.meshBound = in.meshBound;
  const StabilityDecision d = decideStability(in.timeStep, p.criticalStep, switching, in.check);
  if (d.refused)
    throwInput(in.file, in.analysisPath + "/Time Step", shortNumber(in.timeStep),
               d.reason + "; the highest frequency is at most " + shortNumber(w) +
                   " rad/s with the mesh, penalty contact and links",
               "use a time step at most " + shortNumber(d.stableStep) + " s, or set 'Stability Check' to 'substep'");
  if (d.warned) p.stabilityWarning = d.reason;
  checkStepCount(nominalSteps(0.0, in.span, in.timeStep), d.substeps, in.limits, in.file, in.analysisPath,
                 in.timeStep);
  p.substeps = d.substeps;
  return p;
}

}  // namespace choc
