// How contact is enforced in a run: the one contact type the structural operator sees (the
// shape 4C gives its contact strategies). A strategy owns the decisions on the active set (the
// statuses and pressures of the constraints: their first state, the complementarity test after a
// solve, the multipliers' corrections) and its rows of the Newton correction: the entries it adds
// to the effective matrix W (whose bulk aM M + aK K physics assembles), the rows it appends, the
// right-hand side of them and what it takes from the solution. Below it lies the contact
// geometry (ContactManager: pairs, followed surfaces, obstacles, constraint rows B_s, gaps, and
// the statuses and pressures it reports) and the Coulomb friction layer over that geometry.
//
//   penalty            springs k B_s^T B_s of the active nodes in W           (PenaltyStrategy)
//   saddle point       the multipliers as unknowns: W extended by their rows   (SaddlePointStrategy)
//   condensed          multipliers eliminated node by node (obstacles alone)   (CondensedStrategy)
//   projected          multipliers projected out of an iterative solve         (ProjectedStrategy)
//   forward increments explicit central differences: no Newton rows at all     (ForwardIncrementStrategy)
// contact/ContactStrategies.hpp chooses one for a scheme, a method and a linear solver, and
// refuses the combinations that cannot work.
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "contact/ContactManager.hpp"
#include "contact/MatrixEntry.hpp"
#include "core/TpetraTypes.hpp"
#include "restart/StateArchive.hpp"
#include "solvers/ConstraintProjector.hpp"

namespace choc {

class ContactStrategy {
 public:
  explicit ContactStrategy(ContactManager& geometry) : geometry_(geometry) {}
  virtual ~ContactStrategy() = default;
  ContactStrategy(const ContactStrategy&) = delete;
  ContactStrategy& operator=(const ContactStrategy&) = delete;

  // How the log names the pressures' place: "" (on their own rows, or none), ", condensed ...".
  virtual std::string pressuresNote() const { return ""; }
  ContactManager& geometry() { return geometry_; }
  const ContactManager& geometry() const { return geometry_; }

  // ---- The residual and the active set
  // out -= the contact forces (normal and friction) on the rows this rank owns; returns the norm
  // of the constraint rows' residual (0 without multiplier rows). A trial: friction keeps the
  // law's state of this evaluation for the tangent.
  virtual double addForces(const Vector& u, Vector& out) { return geometry_.addForces(u, out); }
  // Statuses from the gaps at u, the pressures 0; the accepted state. Collective.
  void initialize(const Vector& u);
  // The method's complementarity test after a solve (all ranks agree).
  virtual StatusUpdate updateStatus(const Vector& u);
  // A line search shortened the last correction: its change of the pressures likewise.
  virtual void scaleLastCorrection(double factor) { geometry_.activeSet().scaleLastCorrection(factor); }

  // ---- Its rows of the Newton correction (W x = b on the DOF map, or extended)
  // A new effective system on the DOF map (built again when the pairing's topology changes).
  virtual void attach(const RCP<const Map>& /*dofMap*/) {}
  // The multipliers are unknowns of the system, on rows of their own.
  virtual bool extendsSystem() const { return false; }
  // Appends the global ids of the rows this rank owns beyond the DOFs (nU of them).
  virtual void appendRows(GO /*nU*/, int /*rank*/, std::vector<GO>& /*gids*/) {}
  // Local row of constraint s's multiplier on this rank, or -1.
  virtual LO multiplierRow(int /*s*/) const { return -1; }
  // Every coupling its entries may take (by local DOF row), for the graph built once.
  void addCouplings(const Map& dofMap, GO nU, std::map<LO, std::vector<GO>>& extra) const;
  // Its entries for the current statuses, in the order they are summed, then friction's tangent.
  std::vector<MatrixEntry> entries(const Map& dofMap, GO nU) const;
  // The multipliers leave the system: their columns' entries go to eliminate(), not to W.
  virtual bool eliminatesMultipliers() const { return false; }
  // After W's values are written (fill resumed): the eliminated multipliers' columns.
  virtual void eliminate(const RCP<CrsMatrix>& /*W*/, std::vector<MatrixEntry> /*columns*/, GO /*nU*/) {}
  // Every row of W changes with the statuses (a refill may not keep any row).
  virtual bool rewritesEveryRow() const { return false; }
  // What the factored matrix depends on besides (aM, aK): statuses, coefficients, friction.
  virtual std::vector<char> statusKey() const;
  // b = -r on the DOF rows (and its own rows' right-hand side) at u.
  virtual void rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b);
  // du from the solution x; the pressures corrected where x holds them (collective).
  virtual void takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du);
  // The projector an iterative solver must apply, or null.
  virtual std::shared_ptr<const ConstraintProjector> projection() const { return nullptr; }
  // The scale of the multiplier rows (a typical diagonal of W), set at each fill.
  void setScale(double s) { geometry_.activeSet().scale = s; }

  // ---- Explicit central differences
  virtual bool incrementsExplicitly() const { return false; }
  // Adds to a the contact accelerations of the sub-step from u to the prediction uStar, and
  // subtracts the contact forces from the residual r (which rigid bodies gather).
  virtual void addExplicitIncrement(const Vector& u, const Vector& uStar, const Vector& inverseMass, double h,
                                    double h2, Vector& a, Vector& r);
  // k_s of an active node, for the critical step: a spring's stiffness, 0 for forward increments.
  virtual double springStiffness() const { return geometry_.method().stiffness(); }

  // ---- The velocity update of an implicit step (Laursen and Love 2002; contact/VelocityUpdate.cpp)
  // After an accepted step: the projection of v (and of a) in the mass's norm that brings every
  // active constraint's gap rate (and gap acceleration) to 0. With a lumped mass (no solveMass):
  // v += W B^T lambda, W the lumped inverse masses (the same at every call). With a consistent
  // mass: v += M^-1 B^T lambda, (B M^-1 B^T) lambda by conjugate gradients preconditioned by the
  // lumped B W B^T, each M^-1 by solveMass. It lowers the kinetic energy 1/2 v^T M v and never
  // raises it. False when no constraint is active (v and a unchanged). Collective. Throws
  // NumericalError when the impulses do not converge.
  using MassInverse = std::function<void(const Vector& b, Vector& x)>;
  bool correctVelocity(Vector& v, Vector& a, const Vector& inverseMass, const MassInverse& solveMass = {});
  void useVelocityUpdate(bool on) { velocityUpdate_ = on; }
  bool updatesVelocity() const { return velocityUpdate_; }

  // ---- The state lifecycle (restart/SteppedState.hpp)
  void beginStep(const Vector& u, double t, double dt) { geometry_.beginStep(u, t, dt); }
  void commitMotion(const Vector& u) { geometry_.commitMotion(u); }
  void commit() { geometry_.activeSet().commit(); }
  void revert() { geometry_.activeSet().revert(); }
  void archive(StateArchive& a) const { geometry_.archive(a); }
  void restore(const StateArchive& a) { geometry_.restore(a); }

 protected:
  // Constraint s's entries for its status, on the DOF rows this rank holds: an active node's
  // spring k B_s^T B_s (none for k = 0); the saddle point adds its multiplier's row and column.
  virtual void addConstraintEntries(int s, const Map& dofMap, GO nU, std::vector<MatrixEntry>& out) const;
  ContactManager& geometry_;
  std::vector<double> inverseMassAtContact_;  // 1/m at the contact DOFs (forward increments, velocity update)
  int inverseMassTopology_ = -1;              // the geometry's topologyVersion() it was gathered for
  bool velocityUpdate_ = false;               // 'Contact Mass' = velocity update
};

}  // namespace choc
