// FiniteStrainForce::validity: every element's det F at its corners and quadrature points, and
// the small-strain blocks' strain and rotation (ElementValidity.hpp).
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CollectiveFailure.hpp"
#include "core/Format.hpp"
#include "fem/ElementChecks.hpp"
#include "physics/FiniteStrainForce.hpp"

namespace choc {

// The smallest det F over the element's checked points where the deformed map's det J is not
// positive (+1 when it is positive everywhere: the reference map, checked at the start, is
// positive at every quadrature point and at a linear element's corners; a quadratic element's
// corner with det J(X) = 0, a quarter-point element's, is not judged); on a small-strain block
// also the strain and rotation at its centre. Each measure keeps the worst value and, on a tie,
// the lowest element.
void FiniteStrainForce::measureElement(const Element& e, const std::vector<double>& ue, Measure& detF,
                                       Measure& strain, Measure& rotation) const {
  const FiniteStrainSolid& k = *e.kernel;
  const CheckPoints& t = checkPoints(k.shape(), k.rule(), k.onePoint());
  const int n = t.nodes, nc = k.componentsPerNode();
  const double* X0 = reference_.data() + referenceAt_[size_t(&e - elements_.data())];
  thread_local std::vector<Point3> X, x;
  X.resize(size_t(n)), x.resize(size_t(n));
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      X[size_t(a)][size_t(i)] = X0[3 * a + i];
      x[size_t(a)][size_t(i)] = X0[3 * a + i] + (i < nc ? ue[size_t(a * nc + i)] : 0.0);
    }
  double J[3][3], smallest = 1.0;
  for (size_t p = 0; p < t.dN.size(); ++p) {
    const double current = mapDeterminant(t, t.dN[p], x, J);
    if (current > 0) continue;
    const double reference = mapDeterminant(t, t.dN[p], X, J);
    if (reference > 0) smallest = std::min(smallest, current / reference);
  }
  keepWorst(detF, smallest, e.number, true);
  if (k.finiteKinematics()) return;
  const auto [eps, omega] = smallStrainAtCentre(t, X, ue, nc, k.kinematics() == Kinematics::Axisymmetric);
  keepWorst(strain, eps, e.number, false);
  keepWorst(rotation, omega, e.number, false);
}

std::string FiniteStrainForce::describeMeasure(const Measure& m, const std::string& text) const {
  std::string line;
  for (const Element& e : elements_)
    if (e.owner && e.number == m.element) line = describe(e, text);
  return collectiveFailure(*K0_->getComm(), line);
}

ElementValidity FiniteStrainForce::validity(const Vector& u) const {
  const Vector& uc = onColumns(u);
  auto data = uc.getData();
  std::vector<double> ue;
  Measure detF, strain, rotation;
  for (const Element& e : elements_) {
    if (!e.owner) continue;
    gather(e, data, ue);
    measureElement(e, ue, detF, strain, rotation);
  }
  const Comm& comm = *K0_->getComm();
  detF = worstOverRanks(comm, detF, true);
  strain = worstOverRanks(comm, strain, false);
  rotation = worstOverRanks(comm, rotation, false);
  ElementValidity v;
  if (detF.element >= 0 && !(detF.value > 0))
    v.failure = describeMeasure(detF, format("inverted: det F = %.4g at a quadrature point or a one-point element's corner (the element "
                                             "has turned inside out; a finer mesh, a smaller step or 'Formulation' = "
                                             "'F-bar' may hold it)", detF.value));
  if (!v.failure.empty()) return v;
  const SmallStrainVerdict w = smallStrainVerdict(strain.value, strain.element >= 0, rotation.value, rotation.element >= 0);
  if (!w.text.empty()) (w.failed ? v.failure : v.warning) = describeMeasure(w.strain ? strain : rotation, w.text);
  return v;
}

}  // namespace choc
