// The critical step of central differences on the deformed mesh, for models with finite-strain
// blocks, whose element stiffness changes as they stretch, compress and turn. Every 'Critical
// Step Interval' steps the finite-strain elements' eigenvalue bound at the current state,
// lambda(u) = max_e lambda_max(K_e(u), M_e) (the tangent against the lumped mass), replaces
// the reference mesh's bound where it is larger:
//
//   omega(u)^2 = max(lambda_mesh, lambda(u)) + lambda_couplings
//
// (lambda_couplings: Gershgorin's bound of the penalty contact and links the plan added to the
// mesh's; Weyl's inequality makes the sum an upper bound), and the stability policy decides
// again with the same damping and share (timeint/StabilityPolicy.hpp): 'refuse' stops the run
// (a numerical failure, exit 2, naming the time and the stable step), 'warn' warns once,
// 'substep' sets the sub-steps. Without an element bound of the mesh (a redistributed contact
// mass), omega scales with sqrt(lambda(u) / lambda(u0)).
#pragma once
#include <string>

#include "analysis/ExplicitPlan.hpp"
#include "physics/StructuralOperator.hpp"

namespace choc {

class DeformedStability {
 public:
  DeformedStability(const StructuralOperator& op, const ExplicitPlan& plan, double rayleighK, double rayleighM,
                    double timeStep, StabilityCheck check, std::string label)
      : op_(op), plan_(plan), rayleighK_(rayleighK), rayleighM_(rayleighM), timeStep_(timeStep), check_(check),
        label_(std::move(label)) {}
  // The sub-steps per step at u (t and n for the messages). Collective.
  int operator()(const Vector& u, double t, long long n);

 private:
  double omegaAt(double lambda);
  const StructuralOperator& op_;
  ExplicitPlan plan_;
  double rayleighK_, rayleighM_, timeStep_;
  StabilityCheck check_;
  std::string label_;
  double lambda0_ = -1.0;  // lambda(u) at the first estimate
  int substeps_ = -1;      // the last decision, for the log
  bool warned_ = false;
};

}  // namespace choc
