// The second-order operator of a structural model (its internal force and tangent: an
// InternalForce; its mass and Rayleigh damping: MassDamping; its loads: Loads) with contact and
// shock links: what DirectTransient gives its steppers.
//   M a + C v + f_int(u) + f_c(u) + f_l(u, v) = f,   C = a_K K0 + a_M M.
// Newton corrections solve with the effective matrix W = ca M + cv C + cd K_T(u) plus the
// contact block (ContactSystem) and the links' tangent, factored by the linear solver only when
// the key (ca, cv, cd, the tangent's version, the statuses of the contact nodes, the links'
// tangent key) changes; the key is compared in full, so a stale matrix is impossible. Timings go to the analysis' stacked timer under "Transient: assembly",
// "Transient: linear solve" and "Transient: contact".
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "core/TimerScope.hpp"
#include "physics/SmallStrainDomain.hpp"
#include "contact/ContactManager.hpp"
#include "contact/ContactSystem.hpp"
#include "physics/KeptFactorization.hpp"
#include "physics/DirectLinks.hpp"
#include "physics/InternalForce.hpp"
#include "physics/MassDamping.hpp"
#include "physics/Loads.hpp"
#include "physics/ProductCache.hpp"
#include "solvers/FactorizationKey.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/ExplicitOperator.hpp"

namespace choc {

class StructuralOperator : public ExplicitOperator {
 public:
  // loads, contact and links may be null. The solver is owned; the contact manager and the
  // links are not.
  StructuralOperator(std::shared_ptr<InternalForce> internal, RCP<const CrsMatrix> M, double rayleighK,
                     double rayleighM, std::shared_ptr<const Loads> loads, ContactManager* contact,
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
  void relaxNextCorrection(double relative) override { nextLooser_ = relative; }
  // With massless DOFs (rows of M that are zero: redistributed contact mass) the initial
  // acceleration is solved by blocks (physics/MasslessInitialAcceleration.hpp). Otherwise the default (W = M).
  CorrectionStatus solveInitialAcceleration(const Vector& u, const Vector& r, Vector& a) override;
  ConstraintUpdate updateConstraints(const Vector& u) override;
  // A linear internal force and constant-in-u loads: linear unless friction (stick and slip
  // decided at every residual) or shock links (their status likewise) act.
  bool linearWithinPass() const override {
    return internal_->linear() && !links_ && !(contact_ && contact_->hasFriction());
  }
  bool residualHasKinks() const override { return internal_->hasReturnMap(); }
  void scaleLastCorrection(double factor) override {
    if (contact_ && !forwardIncrement_) contact_->scaleLastCorrection(factor);
  }
  void beginStep(const Vector& u, double t, double dt) override;
  void commitMotion(const Vector& u) override;
  // The elements' validity, the assembled small-strain blocks' domain, then the slave nodes'
  // penetration of rigid obstacles.
  ElementValidity validity(const Vector& u) const override;
  void setSmallStrainDomain(std::shared_ptr<const SmallStrainDomain> d) { domain_ = std::move(d); }
  double elasticTermsNorm(const Vector& u) const override;
  bool forcesVaryInTime() const override { return loads_ && loads_->ramped(); }
  void keepProducts(bool on) override { keepProducts_ = on; }
  // Explicit runs with a multiplier method: contact by forward increments (ContactManager::
  // forwardIncrement) instead of forces and statuses.
  void setForwardIncrementContact(bool on) {
    forwardIncrement_ = on;
    if (contact_) contact_->useForwardIncrements(on);
  }
  // The contact multipliers condensed out of the Newton system where they can be
  // (ContactCondensation: every constraint against a rigid obstacle, no friction).
  void setCondensedContact(bool on) { condense_ = on; }
  bool condensedContact() const { return condense_ && contact_ && ContactCondensation::applies(*contact_); }
  // Lagrange with a pair between meshed bodies: the multipliers projected out (ContactProjection).
  bool projectedContact() const {
    return condense_ && contact_ && !ContactCondensation::applies(*contact_) && ContactProjection::applies(*contact_);
  }
  // The internal force's products from half a symmetric matrix (InternalForce::
  // preferSymmetricProducts): for explicit runs, whose cost is those products. Implicit runs
  // keep the CRS product: their linear solve dominates, and the copy costs 0.4 kB per unknown.
  void storeStiffnessSymmetrically() { internal_->preferSymmetricProducts(); }
  // M is the diagonal m (a lumped mass: explicit runs): its products element by element, and
  // applyForces' damping term aM m .* v added in the same pass.
  void useDiagonalMass(RCP<const Vector> m) { mass_.useDiagonal(std::move(m)); }
  bool hasExplicitContact() const override { return contact_ && forwardIncrement_; }
  void addExplicitContact(const Vector& u, const Vector& uStar, const Vector& inverseMass, double h, double h2,
                          Vector& a) override;
  std::string constraintState() const override { return contact_ ? contact_->activeSummary() : ""; }
  void initializeConstraints(const Vector& u) override;
  void commit() override;
  void revert() override;
  void archive(StateArchive& a) const override;
  void restore(const StateArchive& a) override;

  const DirectLinks* links() const { return links_; }
  // The state-dependent elements' eigenvalue bound at u (InternalForce::stateEigenvalueBound).
  double stateEigenvalueBound(const Vector& u) const { return internal_->stateEigenvalueBound(u); }
  // The internal force's element variables (InternalForce::elementFieldNames).
  const InternalForce& internalForce() const { return *internal_; }
  // Energies of a state, for the output: 1/2 v.M v, the stored elastic energy, the contact springs' energy,
  // the damping power v.C v (given the kinetic energy).
  double kineticEnergy(const Vector& v) const { return mass_.kineticEnergy(v); }
  void massTimes(const Vector& x, Vector& out) const { mass_.applyMass(x, out); }  // out = M x
  double strainEnergy(const Vector& u) const;
  double contactEnergy(const Vector& u) const { return contact_ ? contact_->energy(u) : 0.0; }
  // Work of the contact pairs' friction dissipated since the start [J].
  double frictionDissipation() const { return contact_ ? contact_->frictionDissipation() : 0.0; }
  double dampingPower(const Vector& v, double kinetic) const { return mass_.dampingPower(v, kinetic); }
  const Loads* loads() const { return loads_.get(); }  // null: none

  int factorizations() const { return solver_->factorizations(); }
  int keptFactorizations() const { return solver_->updates(); }
  const LinearSolver& solver() const { return *solver_; }
  int unknowns() const;  // global rows of the solved system (DOFs + pressure unknowns)
  long long masslessDofs() const { return mass_.masslessDofs(); }  // DOFs whose mass row is zero
  const std::vector<char>& masslessMask() const { return mass_.masslessMask(); }  // per local DOF

 private:
  ContactSystem& system();
  std::shared_ptr<InternalForce> internal_;
  // The tangent's matrix object (one graph for the run; its values the model's current ones),
  // null until tangentMatrix().
  RCP<const CrsMatrix> K_;
  MassDamping mass_;  // M and C (physics/MassDamping.hpp)
  std::shared_ptr<const Loads> loads_;
  ContactManager* contact_;
  DirectLinks* links_;
  std::unique_ptr<LinearSolver> solver_;
  Teuchos::StackedTimer* timer_;
  std::shared_ptr<const SmallStrainDomain> domain_;  // null: no assembled small-strain solid block
  std::unique_ptr<ContactSystem> system_;
  int systemTopology_ = 0;
  long long filledTangent_ = 0;  // the tangent version the system's K rows were last written from  // the contact manager's topologyVersion() the graph was built for
  bool forwardIncrement_ = false;
  bool condense_ = false;
  // K u of the last applyForces (K v and M v: mass_): the energies of the state a step ended at
  // (whose forces the step's last residual computed) cost no second product with K or M.
  ProductCache ku_;
  bool keepProducts_ = true;
  double nextLooser_ = 0.0;  // relaxNextCorrection's tolerance, for one correction
  RCP<MultiVector> rhs_, x_;
  // What the factored matrix was built from (solvers/FactorizationKey.hpp).
  FactorizationCache factored_;
  FactorizationKey keyOf(const EffectiveCoefficients& c, std::vector<char> status) const;
  // The factored matrix's coupling entries and coefficients, while the solver may keep it
  // through changes of status; a checkpoint's, to rebuild at the first correction.
  KeptFactorization kept_;
  bool restoreKept_ = false;
  int recordedFactorizations_ = -1;  // the solver's factorisations when kept_.factored was taken
  void restoreKeptFactorization();
  void evaluateTangent(const Vector& u);
};

}  // namespace choc
