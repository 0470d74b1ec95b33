// Lagrange multipliers between meshed bodies eliminated from an iterative Newton solve by an
// orthogonal projection. An active constraint s reads c_s^T du = t_s, c_s = B_s^T involving its
// slave node and the nodes of its master face (t_s = rowResidual(s, g_s) / S); with C the active
// columns, G = C^T C (small: one row per active slave node, factored by Cholesky on every rank),
// P = I - C G^-1 C^T and d0 = C G^-1 t, the correction du = d0 + P x solves
//     (P W P + sigma (I - P)) x = P (-R - W d0)
// by CG (solvers/ConstraintProjector.hpp), W untouched: its preconditioner stays when the active
// set changes. The multipliers follow by least squares on the DOF equations,
//     C dlambda = W du + R,   dlambda = G^-1 C^T (W du + R),
// exact where the solve is: the same Newton iterates as the saddle-point system to the solver's
// tolerance. With friction a sliding node's multiplier column is V = C + mu T (its friction force
// grows with lambda; W carries friction's tangent): the rows are projected by the oblique
// P_L = I - V (C^T V)^-1 C^T, which annihilates V, and (C^T V) dlambda = C^T (W du + R); GMRES
// solves (P_L W P + sigma (I - P)) x = P_L (-R - W d0). Applies to Lagrange contact with some pair
// between meshed bodies (ContactCondensation, node by node, serves pairs against obstacles alone).
#pragma once
#include <map>
#include <vector>

#include "contact/ContactManager.hpp"
#include "core/TpetraTypes.hpp"
#include "solvers/ConstraintProjector.hpp"
#include "solvers/ReplicatedSparseLU.hpp"

namespace choc {

class ContactProjection : public ConstraintProjector {
 public:
  ContactProjection(ContactManager& contact, RCP<const Map> dofMap) : contact_(contact), map_(std::move(dofMap)) {}

  void project(const MultiVector& X, MultiVector& Y) const override;
  void projectRows(const MultiVector& X, MultiVector& Y) const override;
  // The saddle-point matrix's entries in the multipliers' columns besides -sigma C (friction's,
  // global column multiplierBase + s; rows this rank owns), from each fill: V = C - entries / sigma.
  void setMultiplierColumns(std::vector<MatrixEntry> entries, GO multiplierBase);
  double scale() const override { return contact_.activeSet().scale; }
  // b = P (-r - W d0) at u, for the current statuses and coefficients (C and G rebuilt when
  // they changed). Throws NumericalError when the active constraints are linearly dependent.
  void rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b);
  // du = P x + d0; the pressures corrected (collective).
  void takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) const;
  int activeConstraints() const { return int(active_.size()); }
  // From this many active constraints G and C^T V are factored sparse (their dense factors take
  // m^2 doubles and m^3 / 3 operations on every rank); settable for the tests of both paths.
  static int sparseFrom;

 private:
  struct Entry {
    LO row;    // local row of the DOF on this rank
    int k;     // active constraint
    double c;  // its coefficient
  };
  ContactManager& contact_;
  RCP<const Map> map_;
  std::vector<char> key_;        // statuses and coefficient version C and G were built for
  bool built_ = false;
  std::vector<int> active_;      // active constraints (indices into the manager's)
  std::vector<Entry> entries_;   // C's entries on the rows this rank owns
  std::vector<double> cholesky_; // G = L L^T, column-major, lower (dense)
  std::vector<double> gram_;     // G's lower triangle (dense)
  bool sparse_ = false;          // G and C^T V factored sparse (from sparseFrom constraints)
  std::vector<ReplicatedSparseLU::Entry> gramEntries_;  // G, both triangles (sparse)
  ReplicatedSparseLU sparseG_, sparseCtV_;
  using ConstraintsByDof = std::map<GO, std::vector<std::pair<int, double>>>;  // DOF -> (constraint, coefficient)
  void factorDenseGram(const ConstraintsByDof& byDof);
  void factorSparseGram(const ConstraintsByDof& byDof);
  void throwDependent(int k) const;
  // C^T (V - C) from this rank's rows: (i, j) -> value.
  std::map<std::pair<int, int>, double> localFrictionCoupling() const;
  // Every rank's localFrictionCoupling, as (i, j, value) entries (sparse path).
  std::vector<ReplicatedSparseLU::Entry> frictionCoupling() const;
  std::vector<MatrixEntry> multiplierColumns_;
  GO multiplierBase_ = 0;
  bool oblique_ = false;         // V != C: P_L = I - V (C^T V)^-1 C^T
  std::vector<Entry> frictionEntries_;  // V - C on this rank's rows
  std::vector<double> ctvLU_;    // C^T V, LU-factored (column-major)
  std::vector<int> ctvPivots_;
  void buildOblique();
  void solveCtV(std::vector<double>& y) const;                 // y = (C^T V)^-1 y
  void subtractColumns(const MultiVector& X, MultiVector& Y, bool oblique) const;
  std::vector<double> d0Coef_;   // G^-1 t: d0 = C d0Coef_
  RCP<Vector> residual_;         // R of the last right-hand side
  void build();
  std::vector<double> transposeTimes(const double* x) const;  // C^T x, summed over the ranks
  void solveG(std::vector<double>& y) const;                   // y = G^-1 y
  std::vector<char> key() const;  // what C, G and V depend on
};

}  // namespace choc
