#include "physics/StructuralOperator.hpp"

#include "physics/CriticalStep.hpp"
#include "physics/MasslessInitialAcceleration.hpp"
#include "physics/RigidBodies.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

namespace choc {

StructuralOperator::StructuralOperator(std::shared_ptr<InternalForce> internal, RCP<const CrsMatrix> M,
                                       double rayleighK, double rayleighM, std::shared_ptr<const Loads> loads,
                                       ContactStrategy* contact, DirectLinks* links,
                                       std::unique_ptr<LinearSolver> solver, Teuchos::StackedTimer* timer)
    : internal_(std::move(internal)), mass_(std::move(M), rayleighK, rayleighM, internal_),
      loads_(std::move(loads)), contact_(contact), links_(links), timer_(timer),
      newton_(std::move(solver), mass_, contact, links, timer), ku_(internal_->map(), 1), work_(loads_.get()) {}

// The tangent at u = 0: its matrix object, which each correction refills (solveCorrection).
const RCP<const CrsMatrix>& StructuralOperator::tangentMatrix() {
  if (K_.is_null()) {
    const Vector zero(internal_->map());
    K_ = internal_->tangent(zero);
  }
  return K_;
}

double StructuralOperator::strainEnergy(const Vector& u) const {
  return internal_->strainEnergy(u, ku_.holds(u, 0) ? &ku_.product(0) : nullptr);
}

void StructuralOperator::applyMass(const Vector& a, Vector& out) {
  TimerScope ts(timer_, "Transient: assembly");
  mass_.applyMass(a, out);
}

void StructuralOperator::applyForces(const Vector& u, const Vector& v, double t, Vector& out) {
  TimerScope ts(timer_, "Transient: assembly");
  internal_->setTime(t);  // the follower loads' ramp, for this residual and its correction's tangent
  internal_->internalForce(u, out);
  if (keepProducts_) {
    ku_.reset(u);
    ku_.write(0).assign(out);
  }
  mass_.addDampingForces(v, out, keepProducts_);
  if (loads_) loads_->subtractFrom(t, out);
}

double StructuralOperator::addConstraintForces(const Vector& u, const Vector& v, Vector& out) {
  if (!contact_ && !links_) return 0.0;
  TimerScope ts(timer_, "Transient: contact");
  if (links_) links_->addForces(u, v, out);
  return contact_ ? contact_->addForces(u, out) : 0.0;
}

// The system prepared (a checkpoint's factorisation rebuilt, the graph after a new pairing), then
// the tangent at u, then the solve.
CorrectionStatus StructuralOperator::solveCorrection(const EffectiveCoefficients& c, const Vector& u,
                                                     const Vector& r, Vector& du) {
  newton_.prepare(tangentMatrix(), internal_->tangentVersion());
  {
    // K_'s values at u (a linear model: K, always version 0); the finite-strain elements'
    // tangents count as assembly.
    TimerScope ts(timer_, "Transient: assembly");
    internal_->tangent(u);
  }
  return newton_.solve(c, internal_->tangentVersion(), u, r, du);
}

// Initial acceleration with massless DOFs (redistributed contact mass): by blocks
// (physics/MasslessInitialAcceleration.hpp), the factorisation of A0 dropped afterwards.
CorrectionStatus StructuralOperator::solveInitialAcceleration(const Vector& u, const Vector& r,
                                                              Vector& a) {
  if (mass_.masslessDofs() == 0) return SecondOrderOperator::solveInitialAcceleration(u, r, a);
  newton_.forget();  // the next correction refactors the effective matrix
  const RCP<const CrsMatrix>& Q = mass_.masslessRotation();
  if (Q.is_null())
    return solveMasslessInitialAcceleration(*tangentMatrix(), *mass_.matrix(), mass_.masslessMask(),
                                            newton_.solver(), timer_, r, a);
  // Normal contact mass: the same blocks in the rotated DOFs, where the normals are DOFs.
  const RCP<CrsMatrix> Kr = rotatedMatrix(*Q, *tangentMatrix());
  const RCP<CrsMatrix> Mr = rotatedMatrix(*Q, *mass_.matrix());
  zeroMasslessEntries(*Mr, mass_.masslessMask());
  Vector rr(r.getMap()), ar(a.getMap());
  rotate(*Q, r, rr, true);
  const CorrectionStatus st =
      solveMasslessInitialAcceleration(*Kr, *Mr, mass_.masslessMask(), newton_.solver(), timer_, rr, ar);
  rotate(*Q, ar, a, false);
  return st;
}

void StructuralOperator::beginStep(const Vector& u, double t, double dt) {
  if (links_) links_->beginStep(dt);
  if (!contact_) return;
  TimerScope ts(timer_, "Transient: contact search");
  contact_->beginStep(u, t, dt);
}

double StructuralOperator::elasticTermsNorm(const Vector& u) const { return internal_->termsNorm(u); }

void StructuralOperator::addExplicitContact(const Vector& u, const Vector& uStar, const Vector& inverseMass,
                                            double h, double h2, Vector& a, Vector& r) {
  TimerScope ts(timer_, "Transient: contact");
  contact_->addExplicitIncrement(u, uStar, inverseMass, h, h2, a, r);
}

SecondOrderOperator::CorrectedFields StructuralOperator::correctVelocity(Vector& v, Vector& a) {
  CorrectedFields out;
  if (!contact_ || !contact_->updatesVelocity()) return out;
  TimerScope ts(timer_, "Transient: contact");
  if (lumpedInverse_.is_null()) {
    // A lumped mass: its own inverse. A consistent one: its diagonal's, the preconditioner of
    // the projection in M's norm (a row sum can be negative: TET10's corners).
    consistentMass_ = lumpedMassDiagonal(*mass_.matrix()).is_null();
    lumpedInverse_ = rcp(new Vector(map()));
    if (consistentMass_) {
      mass_.matrix()->getLocalDiagCopy(*lumpedInverse_);
    } else {
      Vector one(map());
      one.putScalar(1.0);
      mass_.applyMass(one, *lumpedInverse_);
    }
    lumpedInverse_->reciprocal(*lumpedInverse_);
  }
  const double before = mass_.kineticEnergy(v);
  const ContactStrategy::MassInverse solve = [this](const Vector& b, Vector& x) { mass_.solveMass(b, x); };
  if (!contact_->correctVelocity(v, a, *lumpedInverse_, consistentMass_ ? solve : ContactStrategy::MassInverse()))
    return out;
  work_.velocityUpdate += before - mass_.kineticEnergy(v);
  out.acceleration = true;
  out.forces = mass_.damps() || links_;
  return out;
}

void StructuralOperator::commitMotion(const Vector& u) {
  if (!contact_) return;
  TimerScope ts(timer_, "Transient: contact search");
  contact_->commitMotion(u);
}

ConstraintUpdate StructuralOperator::updateConstraints(const Vector& u) {
  ConstraintUpdate up;
  if (!contact_) return up;
  TimerScope ts(timer_, "Transient: contact");
  const StatusUpdate s = contact_->updateStatus(u);
  up.changed = s.changed;
  up.active = s.active;
  up.summary = std::to_string(s.entered) + " entered, " + std::to_string(s.left) + " left, " +
               std::to_string(s.active) + " active" + (s.where.empty() ? "" : " in " + s.where);
  return up;
}

void StructuralOperator::initializeConstraints(const Vector& u) {
  if (contact_) contact_->initialize(u);
}
ElementValidity StructuralOperator::validity(const Vector& u) const {
  TimerScope ts(timer_, "Transient: validity");
  ElementValidity v = internal_->validity(u);
  if (domain_) domain_->check(u, v);
  if (contact_) contact_->geometry().checkPenetration(u, v);
  return v;
}

void StructuralOperator::commit() {
  internal_->commit();
  if (links_) links_->commit();
  if (contact_) contact_->commit();
}
void StructuralOperator::revert() {
  internal_->revert();
  if (links_) links_->revert();
  if (contact_) contact_->revert();
}
void StructuralOperator::archive(StateArchive& a) const {
  internal_->archive(a);
  if (mass_.rigidBodies()) mass_.rigidBodies()->archive(a);
  if (contact_) contact_->archive(a);
  if (links_) links_->archive(a);
  newton_.archive(a, *internal_->map()->getComm());
}
void StructuralOperator::restore(const StateArchive& a) {
  internal_->restore(a);
  if (mass_.rigidBodies()) mass_.rigidBodies()->restore(a);
  if (contact_) contact_->restore(a);
  if (links_) links_->restore(a);
  newton_.restore(a, *internal_->map()->getComm());
}

// The damping's and the moving obstacles' work by the trapezoidal rule on their power, the
// loads' by LoadWork, the rigid bodies' holds' and gravity's by RigidBodies.
StateEnergies StructuralOperator::energies(const Vector& u, const Vector& v, const Vector& a, double time, double dt,
                                           double substep) {
  StateEnergies e;
  e.kinetic = mass_.kineticEnergy(v);
  e.strain = strainEnergy(u);
  e.contact = (contact_ ? contact_->geometry().energy(u) : 0.0) + (links_ ? links_->springEnergy() : 0.0);
  const double power = mass_.dampingPower(v, e.kinetic);
  work_.damping += 0.5 * dt * (work_.lastDampingPower + power);
  work_.lastDampingPower = power;
  if (mass_.rigidBodies()) e.kinetic += mass_.rigidBodies()->kineticEnergy();  // undamped
  const double friction =
      contact_ && contact_->geometry().hasFriction() ? contact_->geometry().friction()->dissipation() : 0.0;
  e.dissipated = work_.damping + (links_ ? links_->dissipatedEnergy() : 0.0) + friction + internal_->dissipatedWork() +
                 work_.velocityUpdate;
  e.plastic = internal_->dissipatedWork();
  e.hourglass = internal_->hourglassEnergy(u);
  const double obstaclePower = contact_ ? obstaclePowerAt(contact_->geometry(), u) : 0.0;
  work_.obstacles += 0.5 * dt * (work_.lastObstaclePower + obstaclePower);
  work_.lastObstaclePower = obstaclePower;
  e.external = work_.loadWork.update(u, time) + work_.obstacles +
               (mass_.rigidBodies() ? mass_.rigidBodies()->externalWork() : 0.0);
  // Central differences: the part of the energy the scheme's conserved energy leaves out,
  // (h^2/8) a^T M a = (h^2/4) x "the kinetic energy of a".
  if (substep > 0) e.shadow = 0.25 * substep * substep * mass_.kineticEnergy(a);
  return e;
}

}  // namespace choc
