// What the direct transient's explicit scheme (central differences) needs before its first
// step: the lumped mass and its inverse, the bound of the highest frequency (the mesh, penalty
// contact and shock links: physics/CriticalStep.hpp), the critical step with the Rayleigh
// damping at that frequency, and the stability policy's decision (timeint/StabilityPolicy.hpp):
// refused (an input error naming the stable step), warned, or the sub-steps per step.
#pragma once
#include <string>

#include "observers/RunLimits.hpp"
#include "contact/ContactStrategy.hpp"
#include "physics/CriticalStep.hpp"
#include "timeint/StabilityPolicy.hpp"

namespace choc {

struct ExplicitPlan {
  RCP<Vector> inverseMass;         // 1 / M_ii
  RCP<const Vector> massDiagonal;  // M_ii
  FrequencyBound bound;
  double criticalStep = 0;
  int substeps = 1;
  Switching switching = Switching::None;  // what switches on and off (the stable step's share)
  double meshBound = 0;                   // the element bound the plan used (infinite: none)
  std::string stabilityWarning;  // 'Stability Check' = warn above the stable step
};

struct ExplicitInputs {
  const CrsMatrix& K;
  const CrsMatrix& M;                // the run's mass (lumped; possibly redistributed)
  const ContactStrategy* contact;    // may be null
  const DirectLinks* links;          // may be null
  double meshBound;                  // the element bound of (K, M), infinity when M is not the mesh's own
  double rayleighK, rayleighM;
  double timeStep, span;  // the run's span: End Time - Start Time
  StabilityCheck check;
  const RunLimits& limits;
  std::string file, analysisPath;  // for the errors: "Analyses/<name>"
};

// Throws InputError: a mass that is not diagonal and positive ('Scheme'), a step refused by the
// stability policy ('Time Step'), a step count past the run limits.
ExplicitPlan planExplicit(const ExplicitInputs& in);

}  // namespace choc
