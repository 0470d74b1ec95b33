// The contact strategies (contact/ContactStrategy.hpp) and the one factory that chooses among
// them for a scheme, a contact method and a linear solver, with every refusal of a combination
// that cannot work (its message naming the parameter, the value and what would be valid):
//
//   scheme     method                 linear solver          strategy
//   explicit   Penalty                (none)                 penalty springs
//   explicit   Lagrange               (none)                 forward increments
//   explicit   Continuous             refused: pressure unknowns need a solve
//   implicit   Penalty                any                    penalty springs
//   implicit   Lagrange / Continuous, every pair against a rigid obstacle, iterative: condensed
//   implicit   Lagrange, some pair between meshed bodies, iterative:                projected
//   implicit   otherwise with multipliers (a direct solver; Continuous between bodies): saddle point
// and refused: friction with an explicit scheme unless Lagrange, friction with CG (a sliding
// node's tangent is not symmetric), a saddle point with CG (indefinite) or with multigrid (its
// multiplier rows are not elasticity's).
#pragma once
#include <memory>
#include <string>

#include "contact/ContactBodies.hpp"
#include "contact/ContactParameters.hpp"
#include "contact/ContactStrategy.hpp"

namespace choc {

class ContactCondensation;
class ContactProjection;

// The scheme and linear solver a contact strategy serves.
struct ContactSolveChoice {
  bool explicitScheme = false;
  std::string linearMethod;    // 'Linear Solver/Method' once 'auto' is resolved: Direct, CG, GMRES...
  std::string preconditioner;  // 'Linear Solver/Preconditioner'
};

// Throws InputError (file, the analysis' parameter) for a combination the strategies refuse.
// Called when the analysis reads its input, before any mesh is read.
void checkContactChoice(const ContactSettings& s, const ContactSolveChoice& c, const std::string& file);
// The strategy of the settings over the manager (which it references: it must outlive it).
std::unique_ptr<ContactStrategy> makeContactStrategy(const ContactSettings& s, ContactManager& geometry,
                                                     const ContactSolveChoice& c);

// Springs k B_s^T B_s of the active nodes (Penalty; the explicit scheme's too).
class PenaltyStrategy : public ContactStrategy {
 public:
  using ContactStrategy::ContactStrategy;
};

// The multipliers on rows of their own (contact/SaddlePointStrategy.cpp).
class SaddlePointStrategy : public ContactStrategy {
 public:
  using ContactStrategy::ContactStrategy;
  bool extendsSystem() const override { return geometry_.numConstraints() > 0; }
  void appendRows(GO nU, int rank, std::vector<GO>& gids) override;
  LO multiplierRow(int s) const override { return rowOfConstraint_[size_t(s)]; }
  void rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) override;
  void takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) override;

 protected:
  void addConstraintEntries(int s, const Map& dofMap, GO nU, std::vector<MatrixEntry>& out) const override;

 private:
  std::vector<LO> rowOfConstraint_;  // local row of each constraint's multiplier, or -1
};

// Multipliers eliminated node by node, every pair against a rigid obstacle (ContactCondensation).
class CondensedStrategy : public ContactStrategy {
 public:
  explicit CondensedStrategy(ContactManager& geometry);
  ~CondensedStrategy() override;
  std::string pressuresNote() const override { return ", condensed out of the Newton system node by node"; }
  void attach(const RCP<const Map>& dofMap) override;
  bool eliminatesMultipliers() const override { return true; }
  void eliminate(const RCP<CrsMatrix>& W, std::vector<MatrixEntry> columns, GO nU) override;
  bool rewritesEveryRow() const override { return true; }
  void rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) override;
  void takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) override;

 private:
  std::unique_ptr<ContactCondensation> condensation_;
};

// Lagrange multipliers between meshed bodies projected out of an iterative solve
// (ContactProjection): without friction W holds no contact term at all.
class ProjectedStrategy : public ContactStrategy {
 public:
  using ContactStrategy::ContactStrategy;
  std::string pressuresNote() const override {
    return ", projected out of the Newton system (C^T du = t by P = I - C (C^T C)^-1 C^T)";
  }
  void attach(const RCP<const Map>& dofMap) override;
  bool eliminatesMultipliers() const override { return true; }
  void eliminate(const RCP<CrsMatrix>& W, std::vector<MatrixEntry> columns, GO nU) override;
  std::vector<char> statusKey() const override;
  void rightHandSide(const CrsMatrix& W, const Vector& r, const Vector& u, MultiVector& b) override;
  void takeSolution(const CrsMatrix& W, const MultiVector& x, Vector& du) override;
  std::shared_ptr<const ConstraintProjector> projection() const override;

 private:
  std::shared_ptr<ContactProjection> projection_;
};

// Lagrange contact of explicit central differences by forward increments (Carpenter, Taylor and
// Katona 1991; contact/ForwardIncrementStrategy.cpp): no force in the residual, no Newton status.
class ForwardIncrementStrategy : public ContactStrategy {
 public:
  explicit ForwardIncrementStrategy(ContactManager& geometry);
  double addForces(const Vector& /*u*/, Vector& /*out*/) override { return 0.0; }
  StatusUpdate updateStatus(const Vector& /*u*/) override { return {}; }  // decided by the increments
  void scaleLastCorrection(double /*factor*/) override {}
  bool incrementsExplicitly() const override { return true; }
  void addExplicitIncrement(const Vector& u, const Vector& uStar, const Vector& inverseMass, double h, double h2,
                            Vector& a, Vector& r) override;
  double springStiffness() const override { return 0.0; }
  // Rigid bodies moving some contact DOFs (their inverse mass 0): the pressures move the bodies.
  void moveWithBodies(const ContactBodies* bodies) { bodies_ = bodies; }

 private:
  const ContactBodies* bodies_ = nullptr;
};

}  // namespace choc
