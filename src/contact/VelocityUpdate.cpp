// The velocity update of Laursen and Love (2002), after an accepted implicit step: the contact
// treatment that keeps the bodies' own mass (contact/ContactStrategy.hpp, correctVelocity).
#include <algorithm>
#include <cmath>

#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactStrategy.hpp"
#include "contact/ForwardIncrementSolver.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {

using Terms = std::vector<std::vector<std::pair<int, double>>>;

// The active constraints' terms (into the contact DOFs), their current rows' values and the
// largest sum of |c| over a row's terms.
struct ActiveRows {
  Terms terms;
  std::vector<double> values;
  double coefficients = 0.0;
};

ActiveRows activeRows(const ContactManager& g, const std::vector<int>& active, const std::vector<double>& values) {
  ActiveRows r;
  for (int s : active) {
    r.terms.push_back(g.localTerms()[size_t(s)]);
    r.values.push_back(values[size_t(s)]);
    double sum = 0.0;
    for (const auto& [k, c] : r.terms.back()) sum += std::abs(c);
    r.coefficients = std::max(r.coefficients, sum);
  }
  return r;
}

// x += scale D B_A^T lambda on the rows this rank owns, D = diag(inverseMass) (null: the identity).
void addTransposed(const ContactManager& g, const std::vector<int>& active, const std::vector<double>& lambda,
                   const Vector* inverseMass, Vector& x) {
  auto xd = x.getDataNonConst();
  Teuchos::ArrayRCP<const double> wd;
  if (inverseMass) wd = inverseMass->getData();
  const Map& map = *x.getMap();
  for (size_t k = 0; k < active.size(); ++k) {
    if (lambda[k] == 0.0) continue;
    for (const auto& [dof, c] : g.constraints()[size_t(active[k])].terms) {
      const LO l = map.getLocalElement(dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) xd[l] += (inverseMass ? wd[l] : 1.0) * c * lambda[k];
    }
  }
}

// B_A x, replicated on every rank (collective).
std::vector<double> rowsOf(const ContactManager& g, const Terms& terms, const Vector& x) {
  const std::vector<double> values = g.contactValues(x);
  std::vector<double> out(terms.size(), 0.0);
  for (size_t k = 0; k < terms.size(); ++k)
    for (const auto& [i, c] : terms[k]) out[k] += c * values[size_t(i)];
  return out;
}

// The lumped Schur complement's solve: lambda with r + B_A W B_A^T lambda = 0 (Gauss-Seidel).
std::vector<double> lumpedImpulses(const ContactManager& g, const Terms& terms, const std::vector<double>& r,
                                   const std::vector<double>& w, const char* what) {
  const ForwardIncrementResult fi = solveForwardIncrement(terms, r, w, 1.0, 1000, false);
  if (!fi.converged)
    throw NumericalError(format("contact velocity update: the %s impulses did not converge in %d sweeps (%s)", what,
                                fi.sweeps, g.activeSummary().c_str()));
  return fi.lambda;
}

double dot(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t k = 0; k < a.size(); ++k) s += a[k] * b[k];
  return s;
}

double largest(const std::vector<double>& a) {
  double m = 0.0;
  for (double x : a) m = std::max(m, std::abs(x));
  return m;
}

// x += M^-1 B_A^T lambda with B_A (x + that) = 0 on the active rows: lambda by conjugate
// gradients on S = B_A M^-1 B_A^T (symmetric positive definite for independent rows),
// preconditioned by the lumped B_A W B_A^T; the change accumulated from each direction's
// M^-1 B_A^T p, so M^-1 is applied once per iteration. Converged at 1e-12 of the largest
// initial row value or of the field's scale (max |x| times a row's sum of |c|): rows already at
// rest to round-off are left as they are.
void projectConsistent(const ContactManager& g, const std::vector<int>& active, const ActiveRows& rows,
                       const std::vector<double>& w, const ContactStrategy::MassInverse& solveMass, Vector& x,
                       const char* what) {
  const size_t n = active.size();
  std::vector<double> res(n), lambda(n, 0.0);
  for (size_t k = 0; k < n; ++k) res[k] = -rows.values[k];  // S lambda = -B_A x
  const double target = 1e-12 * std::max(largest(res), x.normInf() * rows.coefficients);
  if (largest(res) <= target) return;
  auto precondition = [&](const std::vector<double>& r) {
    std::vector<double> minus(r.size());
    for (size_t k = 0; k < r.size(); ++k) minus[k] = -r[k];
    return lumpedImpulses(g, rows.terms, minus, w, what);
  };
  std::vector<double> z = precondition(res), p = z;
  double rz = dot(res, z);
  Vector change(x.getMap()), bt(x.getMap()), mp(x.getMap());
  for (int it = 0; it < 200; ++it) {
    bt.putScalar(0.0);
    addTransposed(g, active, p, nullptr, bt);
    solveMass(bt, mp);
    const std::vector<double> sp = rowsOf(g, rows.terms, mp);
    const double psp = dot(p, sp);
    if (!(psp > 0)) break;
    const double alpha = rz / psp;
    for (size_t k = 0; k < n; ++k) {
      lambda[k] += alpha * p[k];
      res[k] -= alpha * sp[k];
    }
    change.update(alpha, mp, 1.0);
    if (largest(res) <= target) {
      x.update(1.0, change, 1.0);
      return;
    }
    z = precondition(res);
    const double rzNew = dot(res, z);
    for (size_t k = 0; k < n; ++k) p[k] = z[k] + rzNew / rz * p[k];
    rz = rzNew;
  }
  throw NumericalError(format("contact velocity update: the %s impulses in the consistent mass's norm did not converge "
                              "(a residual of %.3e against %.3e; %s)",
                              what, largest(res), target, g.activeSummary().c_str()));
}

// x += W B_A^T lambda with B_A x = 0 on the active rows (lambda of either sign: Gauss-Seidel on
// B_A W B_A^T), on the rows this rank owns.
void projectLumped(const ContactManager& g, const std::vector<int>& active, const ActiveRows& rows,
                   const std::vector<double>& w, const Vector& inverseMass, Vector& x, const char* what) {
  addTransposed(g, active, lumpedImpulses(g, rows.terms, rows.values, w, what), &inverseMass, x);
}

}  // namespace

// Every constraint active at the end of the step keeps its surface: its gap rate and gap
// acceleration are brought to 0 (the obstacles move at constant velocity) by the projection in
// the mass's norm, v and a moved only along the constraints' rows (lumped) or by M^-1 of them.
bool ContactStrategy::correctVelocity(Vector& v, Vector& a, const Vector& inverseMass, const MassInverse& solveMass) {
  const ContactManager& g = geometry_;
  const ContactActiveSet& set = g.activeSet();
  std::vector<int> active;
  for (int s = 0; s < g.numConstraints(); ++s)
    if (set.status[size_t(s)]) active.push_back(s);
  if (active.empty()) return false;
  if (inverseMassTopology_ != g.topologyVersion()) {
    inverseMassAtContact_ = g.contactValues(inverseMass);
    inverseMassTopology_ = g.topologyVersion();
  }
  const ActiveRows rates = activeRows(g, active, g.gapRates(v));
  const std::vector<double> x = g.contactValues(a);
  std::vector<double> accelerations(size_t(g.numConstraints()), 0.0);
  for (int s : active)
    for (const auto& [k, c] : g.localTerms()[size_t(s)]) accelerations[size_t(s)] += c * x[size_t(k)];
  const ActiveRows accs = activeRows(g, active, accelerations);
  if (solveMass) {
    projectConsistent(g, active, rates, inverseMassAtContact_, solveMass, v, "velocity");
    projectConsistent(g, active, accs, inverseMassAtContact_, solveMass, a, "acceleration");
  } else {
    projectLumped(g, active, rates, inverseMassAtContact_, inverseMass, v, "velocity");
    projectLumped(g, active, accs, inverseMassAtContact_, inverseMass, a, "acceleration");
  }
  return true;
}

}  // namespace choc
