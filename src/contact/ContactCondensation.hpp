// Contact multipliers condensed out of the Newton system, node by node, where each constraint
// involves its slave node only (rigid obstacles: B_s = c_s^T on the slave node's components).
// The active constraints of a node a, C_a = [c_s ...], fix the component of its correction in
// span(C_a): C_a^T du_a = t_a (t_s = -g_s for an active node). With P = I - Q Q^T per node (Q an
// orthonormal basis of span(C_a); P = I at the other nodes) and sigma the system's scale, the
// correction solves, on the DOF map alone,
//     (P W P + sigma Q Q^T) du = P (-R - W d0) + sigma d0,     d0_a = C_a (C_a^T C_a)^-1 t_a,
// a matrix with W's graph that is symmetric positive definite where W is (frictionless Lagrange:
// W = aM M + aK K), so CG with Jacobi or multigrid solves it on every rank. The multipliers follow
// from the node's equations before projection: C_a dlambda_a = (W du + R)_a. An inactive node's
// pressure is reset to 0 as in the saddle-point system. The same Newton iterates as the
// saddle-point system (the saddle-point strategy.s extended map), to the solver's tolerance.
// With friction the sliding node's rows carry its multiplier through V_a = C_a + mu T_a (the
// friction force mu lambda t grows with lambda): the node's rows are projected by
// P_L = I - V_a (Q^T V_a)^-1 Q^T, which annihilates V_a, instead of P; then
//     (P_L W P + sigma Q Q^T) du = P_L (-R - W d0) + sigma d0,   (Q^T V_a) dlambda_a = Q^T (W du + R)_a,
// W with friction's tangent: not symmetric (GMRES), equal to P W P where nothing slides.
#pragma once
#include <vector>

#include "contact/ContactManager.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

class ContactCondensation {
 public:
  explicit ContactCondensation(ContactManager& contact) : contact_(contact) {}

  // A holds W (values written, fill resumed; DOF map): saves what the right-hand side and the
  // multipliers need, then writes P W P + sigma Q Q^T in place for the current statuses. Throws
  // NumericalError when a node's active constraints are linearly dependent.
  // multiplierColumns: the entries of the saddle-point matrix in the multipliers' columns (global
  // column multiplierBase + s, the unknown lambda_s / sigma) besides -sigma B^T: friction's.
  void project(const RCP<CrsMatrix>& A, const std::vector<MatrixEntry>& multiplierColumns = {},
               GO multiplierBase = 0);
  // b = P (-r - W d0) + sigma d0 at u.
  void rightHandSide(const Vector& r, const Vector& u, MultiVector& b);
  // du = x; the pressures corrected (collective).
  void takeSolution(const MultiVector& x, Vector& du) const;

 private:
  struct Node {
    std::vector<int> constraints;  // active constraints at this node
    std::vector<GO> dofs;          // the components they involve (sorted)
    std::vector<LO> rows;          // local rows of dofs (owner rank), else empty
    std::vector<double> Q;         // dofs.size() x m, column-major, orthonormal: C = Q R
    std::vector<double> R;         // m x m, upper triangular, column-major
    std::vector<double> P;         // dofs.size()^2: I - Q Q^T
    std::vector<double> PL;        // dofs.size()^2: the rows' projector, I - V (Q^T V)^-1 Q^T
    std::vector<double> QtVinv;    // m x m, column-major: (Q^T V)^-1
    std::vector<double> d0;        // dofs.size(): the correction's part in span(C)
    std::vector<double> r;         // the residual at the rows (rightHandSide)
    std::vector<std::vector<std::pair<LO, double>>> wRows;  // W's rows before projection
  };
  struct ColumnEntry {
    LO row;
    int node, pos;
    double value;
  };
  ContactManager& contact_;
  std::vector<Node> nodes_;
  std::vector<ColumnEntry> columns_;  // W's entries in the nodes' columns, before projection
  RCP<const CrsMatrix> matrix_;       // for the column map and its importer
  double sigma_ = 1.0;
  void groupActive(const Map& rows);
  void addFriction(const std::vector<MatrixEntry>& multiplierColumns, GO multiplierBase);
  void projectColumns(CrsMatrix& A);  // W P, saving W's entries in the nodes' columns
  void projectRows(CrsMatrix& A);     // P (W P) + sigma Q Q^T on the rows of the nodes this rank owns
};

}  // namespace choc
