// The effective matrix of an implicit step with contact, built once on a fixed graph and
// refilled (values only) when its key changes:
//   penalty / no contact:   A = aM M + aK K + sum_active k_s B_s^T B_s        (DOF map)
//   multiplier methods:     A = [ aM M + aK K + sum_active k_s B_s^T B_s   -S B_A^T ]
//                               [ -S B_A                                    S I_inactive ]
// on the DOF map extended by one row per slave node (GID numGlobal + s, owned by the slave
// node's rank). S is the manager's scale: the unknowns of those rows are lambda / S, an
// inactive node's row reads lambda = 0. The graph holds every possible coupling, so a change
// of active set keeps the sparsity (the direct solver reuses its symbolic factorisation).
#pragma once
#include "contact/ContactManager.hpp"
#include "fem/TpetraTypes.hpp"

namespace choc {

class ContactSystem {
 public:
  // contact may be null (no contact).
  ContactSystem(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, const ContactManager* contact);
  RCP<const Map> map() const { return map_; }  // DOF map, or extended by the multiplier rows
  bool extended() const { return extended_; }
  size_t numLocalDofs() const { return nLocalDofs_; }  // leading local entries are the DOFs
  // Local row of constraint s on this rank, or -1.
  LO multiplierRow(int s) const { return rowOfConstraint_[s]; }
  // Refills the values: W = aM M + aK K plus the contact block for the current statuses.
  void fill(double aM, double aK);
  RCP<const CrsMatrix> matrix() const { return A_; }

 private:
  RCP<const CrsMatrix> K_, M_;
  const ContactManager* contact_;
  bool extended_ = false;
  size_t nLocalDofs_ = 0;
  RCP<const Map> map_;
  RCP<CrsMatrix> A_;
  std::vector<LO> rowOfConstraint_;
};

}  // namespace choc
