#include "physics/MasslessInitialAcceleration.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "core/TimerScope.hpp"

namespace choc {

MasslessRows masslessRows(const CrsMatrix& M) {
  MasslessRows r;
  const size_t nLocal = M.getNodeNumRows();
  r.mask.assign(nLocal, 0);
  long long mine = 0;
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t i = 0; i < nLocal; ++i) {
    const GO g = M.getRowMap()->getGlobalElement(LO(i));
    const size_t n = M.getNumEntriesInGlobalRow(g);
    ci.resize(n);
    cv.resize(n);
    size_t got = 0;
    M.getGlobalRowCopy(g, ci(), cv(), got);
    bool zero = true;
    for (size_t k = 0; k < got; ++k) zero = zero && cv[k] == 0.0;
    r.mask[i] = zero;
    mine += zero;
  }
  Teuchos::reduceAll<int, long long>(*M.getComm(), Teuchos::REDUCE_SUM, mine,
                                     Teuchos::outArg(r.global));
  return r;
}

namespace {

std::vector<std::vector<std::pair<GO, double>>> initialAccelerationRows(const CrsMatrix& K, const CrsMatrix& M,
                                                                        const std::vector<char>& massless);

// A0 = [M_mm 0; 0 K_zz]: the rows of M on the DOFs with mass, the rows of K restricted to the
// massless columns on the others.
RCP<CrsMatrix> initialAccelerationMatrix(const CrsMatrix& K, const CrsMatrix& M,
                                         const std::vector<char>& massless, Teuchos::StackedTimer* timer) {
  TimerScope ts(timer, "Transient: assembly");
  auto rowMap = K.getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  const std::vector<std::vector<std::pair<GO, double>>> rows = initialAccelerationRows(K, M, massless);
  std::vector<size_t> counts(nLocal);
  for (size_t i = 0; i < nLocal; ++i) counts[i] = rows[i].size();
  RCP<CrsMatrix> A0 = rcp(new CrsMatrix(rowMap, Teuchos::ArrayView<const size_t>(counts)));
  for (size_t i = 0; i < nLocal; ++i) {
    std::vector<GO> c;
    std::vector<double> v;
    for (const auto& [cc, vv] : rows[i]) {
      c.push_back(cc);
      v.push_back(vv);
    }
    A0->insertGlobalValues(rowMap->getGlobalElement(LO(i)), Teuchos::ArrayView<const GO>(c),
                           Teuchos::ArrayView<const double>(v));
  }
  A0->fillComplete(rowMap, rowMap);
  return A0;
}

// A0's entries by local row (global column, value).
std::vector<std::vector<std::pair<GO, double>>> initialAccelerationRows(const CrsMatrix& K, const CrsMatrix& M,
                                                                        const std::vector<char>& massless) {
  auto rowMap = K.getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  Vector zRow(rowMap);
  {
    auto z = zRow.getDataNonConst();
    for (size_t i = 0; i < nLocal; ++i) z[i] = massless[i] ? 1.0 : 0.0;
  }
  Vector zCol(K.getColMap());
  zCol.doImport(zRow, Tpetra::Import<LO, GO>(rowMap, K.getColMap()), Tpetra::INSERT);
  auto zc = zCol.getData();
  auto colMap = K.getColMap();
  std::vector<std::vector<std::pair<GO, double>>> rows(nLocal);
  Teuchos::Array<GO> ci;
  Teuchos::Array<double> cv;
  for (size_t i = 0; i < nLocal; ++i) {
    const GO g = rowMap->getGlobalElement(LO(i));
    const CrsMatrix& X = massless[i] ? K : M;
    const size_t n = X.getNumEntriesInGlobalRow(g);
    ci.resize(n);
    cv.resize(n);
    size_t got = 0;
    X.getGlobalRowCopy(g, ci(), cv(), got);
    for (size_t k = 0; k < got; ++k)
      if (!massless[i] || zc[colMap->getLocalElement(ci[k])] != 0.0) rows[i].emplace_back(ci[k], cv[k]);
  }
  return rows;
}

// The second solve's right-hand side on the massless rows: b_z = -(K [a_m; 0])_z, from the
// first solve's x = (a_m, a_z) (whose a_z it zeroes).
void masslessRightHandSide(const CrsMatrix& K, const std::vector<char>& massless, MultiVector& x,
                           MultiVector& b) {
  auto rowMap = K.getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  {
    auto xd = x.getDataNonConst(0);
    for (size_t i = 0; i < nLocal; ++i)
      if (massless[i]) xd[i] = 0.0;
  }
  Vector y(rowMap);
  K.apply(*x.getVector(0), y);
  auto yd = y.getData();
  auto bd = b.getDataNonConst(0);
  for (size_t i = 0; i < nLocal; ++i)
    if (massless[i]) bd[i] = -yd[i];
}

}  // namespace

// Initial acceleration with massless DOFs (redistributed contact mass). M = [M_mm 0; 0 0]
// (z: the DOFs whose mass row is zero, the nodes of the contact surfaces). Rows m give a_m
// from M_mm a_m = -r_m: the contact forces act on contact-surface DOFs only, so they do not
// enter r_m. Rows z carry no inertia: they are the static equilibrium K_zm u_m + K_zz u_z
// + f_c,z = f_z, which holds at t0 and which every step re-imposes at t_{n+1} whatever a_z
// (u_z is found statically; a_z only feeds v_z through the Newmark relations, and v_z acts
// only through Rayleigh damping). The consistent value is the second time derivative of that
// equilibrium with the contact status and pressures frozen and constant loads:
// K_zz a_z = -K_zm a_m. Both come from A0 = [M_mm 0; 0 K_zz] (symmetric, non-singular: a
// contact-surface node is tied elastically to the massive nodes): a first solve with
// b = (-r_m, 0) gives a_m, a second with b = (-r_m, -(K [a_m; 0])_z) gives (a_m, a_z). The
// contact pressures keep their initial values (the reactions of the static rows, found by the
// first step). The solver is left holding the factorisation of A0.
CorrectionStatus solveMasslessInitialAcceleration(const CrsMatrix& K, const CrsMatrix& M,
                                                  const std::vector<char>& massless, LinearSolver& solver,
                                                  Teuchos::StackedTimer* timer, const Vector& r, Vector& a) {
  CorrectionStatus st;
  auto rowMap = K.getRowMap();
  const size_t nLocal = rowMap->getNodeNumElements();
  RCP<CrsMatrix> A0 = initialAccelerationMatrix(K, M, massless, timer);
  TimerScope ts(timer, "Transient: linear solve");
  solver.setMatrix(A0);
  st.refactored = true;
  MultiVector b(rowMap, 1), x(rowMap, 1);
  {
    auto rd = r.getData();
    auto bd = b.getDataNonConst(0);
    for (size_t i = 0; i < nLocal; ++i) bd[i] = massless[i] ? 0.0 : -rd[i];
  }
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) masslessRightHandSide(K, massless, x, b);
    x.putScalar(0.0);
    const LinearSolveStatus ls = solver.solve(b, x);
    st.ok = ls.converged;
    st.iterations += ls.iterations;
    st.message = ls.message;
    if (!st.ok) return st;
  }
  a.assign(*x.getVector(0));
  return st;
}

}  // namespace choc
