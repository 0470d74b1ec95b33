// The second-order operator of a linear elastic model with Rayleigh damping, constant nodal
// loads and contact: what ImplicitTransient gives its integrator.
//   M a + C v + K u + f_c(u) = f,   C = a_K K + a_M M.
// Newton corrections solve with the effective matrix W = ca M + cv C + cd K plus the contact
// block (ContactSystem), factored by the linear solver only when the key (ca, cv, cd, the
// statuses of the contact nodes) changes; the key is compared in full, so a stale matrix is
// impossible. Timings go to the analysis' stacked timer under "Transient: assembly",
// "Transient: linear solve" and "Transient: contact".
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "contact/ContactManager.hpp"
#include "contact/ContactSystem.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/SecondOrderOperator.hpp"

namespace choc {

// Starts a sub-timer of a StackedTimer for the scope (no-op for a null timer).
class TimerScope {
 public:
  TimerScope(Teuchos::StackedTimer* t, const char* name) : t_(t), name_(name) {
    if (t_) t_->start(name_, false);
  }
  ~TimerScope() {
    if (t_) t_->stop(name_, false);
  }
  TimerScope(const TimerScope&) = delete;
  TimerScope& operator=(const TimerScope&) = delete;

 private:
  Teuchos::StackedTimer* t_;
  const char* name_;
};

class StructuralOperator : public SecondOrderOperator {
 public:
  // load and contact may be null. The solver is owned; the contact manager is not.
  StructuralOperator(RCP<const CrsMatrix> K, RCP<const CrsMatrix> M, double rayleighK,
                     double rayleighM, RCP<const Vector> load, ContactManager* contact,
                     std::unique_ptr<LinearSolver> solver, Teuchos::StackedTimer* timer);

  RCP<const Map> map() const override { return K_->getRowMap(); }
  void applyMass(const Vector& a, Vector& out) override;
  void applyForces(const Vector& u, const Vector& v, double t, Vector& out) override;
  double addConstraintForces(const Vector& u, Vector& out) override;
  CorrectionStatus solveCorrection(const EffectiveCoefficients& c, const Vector& u,
                                   const Vector& r, Vector& du) override;
  // With massless DOFs (rows of M that are zero: redistributed contact mass) the initial
  // acceleration is solved by blocks; see the .cpp. Otherwise the default (W = M).
  CorrectionStatus solveInitialAcceleration(const Vector& u, const Vector& r, Vector& a) override;
  ConstraintUpdate updateConstraints(const Vector& u) override;
  void initializeConstraints(const Vector& u) override;
  void saveState() override;
  void restoreState() override;

  int factorizations() const { return solver_->factorizations(); }
  const LinearSolver& solver() const { return *solver_; }
  int unknowns() const;  // global rows of the solved system (DOFs + pressure unknowns)
  long long masslessDofs() const { return masslessGlobal_; }  // DOFs whose mass row is zero

 private:
  RCP<const CrsMatrix> K_, M_;
  double aK_, aM_;
  RCP<const Vector> load_;
  ContactManager* contact_;
  std::unique_ptr<LinearSolver> solver_;
  Teuchos::StackedTimer* timer_;
  std::unique_ptr<ContactSystem> system_;
  RCP<Vector> tmp_;
  RCP<MultiVector> rhs_, x_;
  double maxDiagK_ = 0, maxDiagM_ = 0;
  std::vector<char> massless_;  // per local DOF: its row of M is zero
  long long masslessGlobal_ = 0;
  // Cache key of the factored matrix.
  bool haveKey_ = false;
  EffectiveCoefficients keyCoefficients_;
  std::vector<char> keyStatus_;
};

}  // namespace choc
