// The linear solve of a Newton correction, W du = -r: the effective system (physics/
// EffectiveSystem.hpp; built at the first correction, again when the contact pairing couples
// other DOFs), the linear solver it owns, the factorisation reused while its key holds (the
// coefficients, the tangent's version, the contact strategy's and the links' keys: compared in
// full, so a stale matrix is impossible; solvers/FactorizationKey.hpp) and the factorisation a
// solver keeps through changes of status, carried through checkpoints (KeptFactorization).
// Timings: "Transient: assembly" (the fill), "Transient: linear solve", "Transient: contact".
#pragma once
#include <memory>
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "contact/ContactStrategy.hpp"
#include "physics/DirectLinks.hpp"
#include "physics/EffectiveSystem.hpp"
#include "physics/KeptFactorization.hpp"
#include "physics/MassDamping.hpp"
#include "solvers/FactorizationKey.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/SecondOrderOperator.hpp"

namespace choc {

class NewtonCorrection {
 public:
  // contact and links may be null; none is owned but the solver.
  NewtonCorrection(std::unique_ptr<LinearSolver> solver, const MassDamping& mass, ContactStrategy* contact,
                   DirectLinks* links, Teuchos::StackedTimer* timer);

  // Before the tangent is evaluated: a checkpoint's kept factorisation rebuilt (once), the
  // system built (or built again after a change of the pairing's topology). K: the tangent's
  // matrix object.
  void prepare(const RCP<const CrsMatrix>& K, long long tangent);
  // W du = -r with W = aM M + aK K_T(u) + contact + links for the coefficients c; tangent: the
  // version of K's values (a new one rewrites every row).
  CorrectionStatus solve(const EffectiveCoefficients& c, long long tangent, const Vector& u, const Vector& r,
                         Vector& du);
  void relaxNextCorrection(double relative) { nextLooser_ = relative; }
  // The factorisation no longer holds (the solver served another matrix).
  void forget() { factored_.forget(); }

  LinearSolver& solver() { return *solver_; }
  const LinearSolver& solver() const { return *solver_; }
  int factorizations() const { return solver_->factorizations(); }
  int keptFactorizations() const { return solver_->updates(); }
  // Global rows of the solved system (DOFs + multiplier rows), or fallback before it is built.
  int unknowns(int fallback) const;

  // The kept factorisation's records (collective), and back: rebuilt at the next correction.
  void archive(StateArchive& a, const Comm& comm) const;
  void restore(const StateArchive& a, const Comm& comm) { restoreKept_ = kept_.restore(a, comm); }

 private:
  std::unique_ptr<LinearSolver> solver_;
  const MassDamping& mass_;
  ContactStrategy* contact_;
  DirectLinks* links_;
  Teuchos::StackedTimer* timer_;
  std::unique_ptr<EffectiveSystem> system_;
  int systemTopology_ = 0;       // the pairing's topologyVersion() the graph was built for
  long long filledTangent_ = 0;  // the tangent version the system's K rows were last written from
  double nextLooser_ = 0.0;      // relaxNextCorrection's tolerance, for one correction
  RCP<MultiVector> rhs_, x_;
  FactorizationCache factored_;  // what the factored matrix was built from
  // The factored matrix's coupling entries and coefficients, while the solver may keep it
  // through changes of status; a checkpoint's, to rebuild at the first correction.
  KeptFactorization kept_;
  bool restoreKept_ = false;
  int recordedFactorizations_ = -1;  // the solver's factorisations when kept_.factored was taken
  void build(const RCP<const CrsMatrix>& K);
  void restoreKeptFactorization(const RCP<const CrsMatrix>& K, long long tangent);
  bool refactor(const EffectiveCoefficients& c, long long tangent);
  FactorizationKey keyOf(const EffectiveCoefficients& c, long long tangent, std::vector<char> status) const;
};

}  // namespace choc
