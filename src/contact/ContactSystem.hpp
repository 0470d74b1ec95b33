// The effective matrix of an implicit step with contact, built once on a fixed graph and
// refilled (values only) when its key changes:
//   penalty / no contact:   A = aM M + aK K + sum_active k_s B_s^T B_s        (DOF map)
//   multiplier methods:     A = [ aM M + aK K + sum_active k_s B_s^T B_s   -S B_A^T ]
//                               [ -S B_A                                    S I_inactive ]
// on the DOF map extended by one row per slave node (GID numGlobal + s, owned by the slave
// node's rank). S is the manager's scale: the unknowns of those rows are lambda / S, an
// inactive node's row reads lambda = 0. The graph holds every possible coupling, so a change
// of active set keeps the sparsity (the direct solver reuses its symbolic factorisation).
// Other nonlinear forces (shock links) add their tangent on couplings declared up front.
//   condensed multipliers:  A = P (aM M + aK K) P + sigma Q Q^T                   (DOF map)
// when asked for and every constraint involves its slave node alone (ContactCondensation).
//   projected multipliers:  A = aM M + aK K (+ friction's tangent), solved as P_L A P + sigma (I - P)
// when asked for, Lagrange, some pair between meshed bodies (ContactProjection; without friction
// the matrix and its preconditioner do not depend on the contact statuses).
#pragma once
#include <memory>

#include "contact/ContactCondensation.hpp"
#include "contact/ContactManager.hpp"
#include "contact/ContactProjection.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

class ContactSystem {
 public:
  // contact may be null (no contact). couplings: groups of DOFs (global ids) that extra
  // tangents couple, each DOF of a group with every other. condense: eliminate the multipliers
  // where ContactCondensation applies.
  ContactSystem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, ContactManager* contact,
                const std::vector<std::vector<GO>>& couplings = {}, bool condense = false);
  ~ContactSystem();
  bool condensed() const { return condensation_ != nullptr; }
  // The projector an iterative solver must apply (ContactProjection), or null.
  std::shared_ptr<const ConstraintProjector> projection() const { return projection_; }
  RCP<const Map> map() const { return map_; }  // DOF map, or extended by the multiplier rows
  bool extended() const { return extended_; }
  size_t numLocalDofs() const { return nLocalDofs_; }  // leading local entries are the DOFs
  // Local row of constraint s on this rank, or -1.
  LO multiplierRow(int s) const { return rowOfConstraint_[s]; }
  // Refills the values: W = aM M + aK K plus the contact block for the current statuses,
  // the multiplier rows scaled by the largest diagonal of aM M + aK K (a balanced system),
  // plus the extra entries (rows this rank owns, within the declared couplings). With the
  // (aM, aK) of the last fill only the rows the coupling entries touch are rewritten.
  void fill(double aM, double aK, const std::vector<MatrixEntry>& extra = {});
  // K's values changed (a nonlinear model's tangent): the next fill rewrites every row, where
  // it would otherwise rewrite only the rows whose coupling entries changed.
  void stiffnessChanged() { filled_ = false; }
  // The same with the coupling entries given (those of an earlier fill, from lastEntries()).
  void fillEntries(double aM, double aK, const std::vector<MatrixEntry>& entries);
  // The coupling entries of the last fill that this rank summed (rows it owns), in order.
  const std::vector<MatrixEntry>& lastEntries() const { return lastEntries_; }
  RCP<const CrsMatrix> matrix() const { return A_; }
  // What the factored matrix depends on besides (aM, aK): the contact statuses and the
  // version of the constraints' coefficients.
  std::vector<char> statusKey() const;

  // b = -r on the DOF rows and, on a multiplier row, the constraint's residual at u.
  void rightHandSide(const Vector& r, const Vector& u, MultiVector& b) const;
  // du = the DOF rows of x; the multiplier rows of x correct the contact pressures.
  void takeSolution(const MultiVector& x, Vector& du) const;

 private:
  RCP<const CrsMatrix> K_, M_;
  ContactManager* contact_;
  double maxDiagK_ = 0, maxDiagM_ = 0;
  bool extended_ = false;
  std::unique_ptr<ContactCondensation> condensation_;
  std::shared_ptr<ContactProjection> projection_;
  void eliminateMultipliers(const RCP<const Map>& dofMap);
  size_t nLocalDofs_ = 0;
  RCP<const Map> map_;
  RCP<CrsMatrix> A_;
  std::vector<LO> rowOfConstraint_;
  // Bulk rows aM M + aK K written through the local arrays: K's and M's column indices as
  // A's (local to each column map), and per column of A its entry in the row being written.
  void fillBulk(double aM, double aK, const std::vector<LO>* rows);
  std::vector<MatrixEntry> couplingEntries(const std::vector<MatrixEntry>& extra) const;
  std::vector<LO> colOfK_, colOfM_, slot_;
  // The last fill: its coefficients and the local rows its coupling entries touched.
  bool filled_ = false;
  double lastAM_ = 0.0, lastAK_ = 0.0;
  std::vector<LO> lastRows_;
  std::vector<MatrixEntry> lastEntries_;
};

}  // namespace choc
