// The second-order operator of a structural model (its internal force and tangent: an
// InternalForce; its mass and Rayleigh damping: MassDamping; its loads: Loads) with contact (a
// ContactStrategy) and shock links: what DirectTransient gives its steppers.
//   M a + C v + f_int(u) + f_c(u) + f_l(u, v) = f,   C = a_K K0 + a_M M.
// Newton corrections solve with the effective matrix W = ca M + cv C + cd K_T(u) plus the
// contact strategy's rows and the links' tangent (physics/NewtonCorrection.hpp: the linear
// solver, its factorisation reused while its key holds). Timings go to the analysis' stacked
// timer under "Transient: assembly", "Transient: linear solve" and "Transient: contact".
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "core/TimerScope.hpp"
#include "physics/SmallStrainDomain.hpp"
#include "contact/ContactStrategy.hpp"
#include "physics/DirectLinks.hpp"
#include "physics/InternalForce.hpp"
#include "physics/MassDamping.hpp"
#include "physics/Loads.hpp"
#include "physics/NewtonCorrection.hpp"
#include "physics/ProductCache.hpp"
#include "physics/StateEnergies.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/ExplicitOperator.hpp"

namespace choc {

class StructuralOperator : public ExplicitOperator {
 public:
  // loads, contact and links may be null. The solver is owned; the contact strategy and the
  // links are not.
  StructuralOperator(std::shared_ptr<InternalForce> internal, RCP<const CrsMatrix> M, double rayleighK,
                     double rayleighM, std::shared_ptr<const Loads> loads, ContactStrategy* contact,
                     DirectLinks* links, std::unique_ptr<LinearSolver> solver,
                     Teuchos::StackedTimer* timer);

  RCP<const Map> map() const override { return internal_->map(); }
  // Newton's schemes take the tangent's matrix object (evaluated at u = 0) before their first
  // step, as the run's start; an explicit run never builds it (its force is element by element,
  // or K u with the linear model's own K).
  const RCP<const CrsMatrix>& tangentMatrix();
  void applyMass(const Vector& a, Vector& out) override;
  void applyForces(const Vector& u, const Vector& v, double t, Vector& out) override;
  double addConstraintForces(const Vector& u, const Vector& v, Vector& out) override;
  CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector& u,
                                   const Vector& r, Vector& du) override;
  void relaxNextCorrection(double relative) override { newton_.relaxNextCorrection(relative); }
  // With massless DOFs (rows of M that are zero: redistributed contact mass) the initial
  // acceleration is solved by blocks (physics/MasslessInitialAcceleration.hpp). Otherwise the default (W = M).
  CorrectionStatus solveInitialAcceleration(const Vector& u, const Vector& r, Vector& a) override;
  ConstraintUpdate updateConstraints(const Vector& u) override;
  // A linear internal force and constant-in-u loads: linear unless friction (stick and slip
  // decided at every residual) or shock links (their status likewise) act.
  bool linearWithinPass() const override {
    return internal_->linear() && !links_ && !(contact_ && contact_->geometry().hasFriction());
  }
  bool residualHasKinks() const override { return internal_->hasReturnMap(); }
  void scaleLastCorrection(double factor) override {
    if (contact_) contact_->scaleLastCorrection(factor);
  }
  void beginStep(const Vector& u, double t, double dt) override;
  void commitMotion(const Vector& u) override;
  // The contact strategy's velocity update ('Contact Mass' = velocity update), its kinetic
  // energy taken counted in the work integrals (energy:dissipated).
  CorrectedFields correctVelocity(Vector& v, Vector& a) override;
  // The elements' validity, the assembled small-strain blocks' domain, then the slave nodes'
  // penetration of rigid obstacles.
  ElementValidity validity(const Vector& u) const override;
  void setSmallStrainDomain(std::shared_ptr<const SmallStrainDomain> d) { domain_ = std::move(d); }
  double elasticTermsNorm(const Vector& u) const override;
  bool forcesVaryInTime() const override { return loads_ && loads_->ramped(); }
  void keepProducts(bool on) override { keepProducts_ = on; }
  // The internal force's products from half a symmetric matrix (InternalForce::
  // preferSymmetricProducts): for explicit runs, whose cost is those products. Implicit runs
  // keep the CRS product: their linear solve dominates, and the copy costs 0.4 kB per unknown.
  void storeStiffnessSymmetrically() { internal_->preferSymmetricProducts(); }
  // M is the diagonal m (a lumped mass: explicit runs): its products element by element, and
  // applyForces' damping term aM m .* v added in the same pass.
  void useDiagonalMass(RCP<const Vector> m) { mass_.useDiagonal(std::move(m)); }
  bool hasExplicitContact() const override { return contact_ && contact_->incrementsExplicitly(); }
  void addExplicitContact(const Vector& u, const Vector& uStar, const Vector& inverseMass, double h, double h2,
                          Vector& a, Vector& r) override;
  std::string constraintState() const override { return contact_ ? contact_->geometry().activeSummary() : ""; }
  void initializeConstraints(const Vector& u) override;
  void commit() override;
  void revert() override;
  void archive(StateArchive& a) const override;
  void restore(const StateArchive& a) override;

  const ContactStrategy* contact() const { return contact_; }  // null: no contact
  // The internal force (its element variables, state-dependent eigenvalue bound, dissipation).
  const InternalForce& internalForce() const { return *internal_; }
  const MassDamping& mass() const { return mass_; }  // M, C, the massless DOFs
  // The run's mass model before the first step: its massless basis ('Contact Mass' = normal: M
  // singular along the contact normals, physics/MasslessBasis.hpp), the direct package of the
  // velocity update's consistent-mass solves (physics/MassDamping.hpp).
  MassDamping& inertia() { return mass_; }
  // The energies of a recorded state (u, the scheme's v and a at time, dt after the last
  // recorded state; substep: an explicit run's sub-step h, else 0) and the work since the start:
  // the damping, obstacles' and loads' work integrated from the last recorded state. Called once
  // per recorded state, in time order.
  StateEnergies energies(const Vector& u, const Vector& v, const Vector& a, double time, double dt, double substep);
  // The stored elastic energy at u (the last residual's K u when it was at u).
  double strainEnergy(const Vector& u) const;
  // The work integrals, for a checkpoint and back.
  WorkIntegrals& work() { return work_; }
  const WorkIntegrals& work() const { return work_; }

  // The Newton correction's solve: its solver, factorisations, unknowns (DOFs + multiplier rows).
  const NewtonCorrection& correction() const { return newton_; }

 private:
  std::shared_ptr<InternalForce> internal_;
  // The tangent's matrix object (one graph for the run; its values the model's current ones),
  // null until tangentMatrix().
  RCP<const CrsMatrix> K_;
  MassDamping mass_;  // M and C (physics/MassDamping.hpp)
  std::shared_ptr<const Loads> loads_;
  ContactStrategy* contact_;
  DirectLinks* links_;
  Teuchos::StackedTimer* timer_;
  std::shared_ptr<const SmallStrainDomain> domain_;  // null: no assembled small-strain solid block
  NewtonCorrection newton_;
  // K u of the last applyForces (K v and M v: mass_): the energies of the state a step ended at
  // (whose forces the step's last residual computed) cost no second product with K or M.
  ProductCache ku_;
  bool keepProducts_ = true;
  WorkIntegrals work_;
  RCP<Vector> lumpedInverse_;  // the velocity update's 1 / (M 1), or 1 / diag(M) for a consistent M; at its first use
  bool consistentMass_ = false;  // the velocity update projects in a consistent M's norm
};

}  // namespace choc
