// The effective matrix of an implicit step, built once on a fixed graph and refilled (values
// only) when its key changes: its bulk rows aM M + aK K here, then the contact strategy's entries
// and rows (contact/ContactStrategy.hpp) and the extra tangents of other nonlinear forces (shock
// links) on couplings declared up front:
//   penalty / no contact:   W = aM M + aK K + sum_active k_s B_s^T B_s                   (DOF map)
//   saddle point:           the DOF map extended by one multiplier row per constraint
//   condensed, projected:   the multipliers eliminated by the strategy                     (DOF map)
// The graph holds every possible coupling, so a change of active set keeps the sparsity (the
// direct solver reuses its symbolic factorisation).
#pragma once
#include <memory>
#include <vector>

#include "contact/ContactStrategy.hpp"
#include "contact/MatrixEntry.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

class EffectiveSystem {
 public:
  // contact may be null (no contact). couplings: groups of DOFs (global ids) that extra
  // tangents couple, each DOF of a group with every other.
  EffectiveSystem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, ContactStrategy* contact,
                  const std::vector<std::vector<GO>>& couplings = {});
  RCP<const Map> map() const { return map_; }  // DOF map, or extended by the strategy's rows
  // Refills the values: W = aM M + aK K plus the strategy's entries for the current statuses,
  // its multiplier rows scaled by the largest diagonal of aM M + aK K (a balanced system), plus
  // the extra entries (rows this rank owns, within the declared couplings). With the (aM, aK) of
  // the last fill only the rows the coupling entries touch are rewritten.
  void fill(double aM, double aK, const std::vector<MatrixEntry>& extra = {});
  // K's values changed (a nonlinear model's tangent): the next fill rewrites every row, where
  // it would otherwise rewrite only the rows whose coupling entries changed.
  void stiffnessChanged() { filled_ = false; }
  // The same with the coupling entries given (those of an earlier fill, from lastEntries()).
  void fillEntries(double aM, double aK, const std::vector<MatrixEntry>& entries);
  // The coupling entries of the last fill that this rank summed (rows it owns), in order.
  const std::vector<MatrixEntry>& lastEntries() const { return lastEntries_; }
  RCP<const CrsMatrix> matrix() const { return A_; }
  // What the factored matrix depends on besides (aM, aK): the strategy's key.
  std::vector<char> statusKey() const { return contact_ ? contact_->statusKey() : std::vector<char>{}; }
  // b = -r on the DOF rows and the strategy's rows at u.
  void rightHandSide(const Vector& r, const Vector& u, MultiVector& b);
  // du from the solution; the strategy takes what it holds of the multipliers.
  void takeSolution(const MultiVector& x, Vector& du);

 private:
  RCP<const CrsMatrix> K_, M_;
  ContactStrategy* contact_;
  double maxDiagK_ = 0, maxDiagM_ = 0;
  size_t nLocalDofs_ = 0;
  RCP<const Map> map_;
  RCP<CrsMatrix> A_;
  // Bulk rows aM M + aK K written through the local arrays: K's and M's column indices as
  // A's (local to each column map), and per column of A its entry in the row being written.
  void fillBulk(double aM, double aK, const std::vector<LO>* rows);
  void buildMatrix(const std::vector<std::vector<GO>>& couplings);
  std::vector<LO> colOfK_, colOfM_, slot_;
  // The last fill: its coefficients and the local rows its coupling entries touched.
  bool filled_ = false;
  double lastAM_ = 0.0, lastAK_ = 0.0;
  std::vector<LO> lastRows_;
  std::vector<MatrixEntry> lastEntries_;
};

}  // namespace choc
