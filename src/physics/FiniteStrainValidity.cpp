// FiniteStrainForce::validity: every element's det F at its corners and quadrature points, and
// the small-strain blocks' strain and rotation (ElementValidity.hpp).
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/CollectiveFailure.hpp"
#include "core/Format.hpp"
#include "fem/IsoparametricPoint.hpp"
#include "physics/FiniteStrainForce.hpp"

namespace choc {

namespace {

// The natural points an element is checked at: its corners, then its quadrature points.
std::vector<Point3> checkedPoints(const FiniteStrainSolid& k) {
  const std::vector<Point3>& nodes = nodeNaturalCoordinates(k.shape());
  std::vector<Point3> xi(nodes.begin(), nodes.begin() + cornerCount(k.shape()));
  xi.insert(xi.end(), k.rule().points.begin(), k.rule().points.end());
  return xi;
}

Point3 centroid(SolidShape t) {
  const std::vector<Point3>& nodes = nodeNaturalCoordinates(t);
  Point3 c{0, 0, 0};
  for (int a = 0; a < cornerCount(t); ++a)
    for (int i = 0; i < 3; ++i) c[size_t(i)] += nodes[size_t(a)][size_t(i)] / cornerCount(t);
  return c;
}

}  // namespace

// The smallest det F over the element's checked points; on a small-strain block also the strain
// and rotation at its centre. Each measure keeps the worst value and, on a tie, the lowest element.
void FiniteStrainForce::measureElement(const Element& e, const std::vector<double>& ue, Measure& detF,
                                       Measure& strain, Measure& rotation) const {
  const FiniteStrainSolid& k = *e.kernel;
  const SolidShape t = k.shape();
  const int n = k.numNodes(), nc = k.componentsPerNode();
  const double* X0 = reference_.data() + referenceAt_[size_t(&e - elements_.data())];
  std::vector<Point3> X(static_cast<size_t>(n)), x(static_cast<size_t>(n));
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      X[size_t(a)][size_t(i)] = X0[3 * a + i];
      x[size_t(a)][size_t(i)] = X0[3 * a + i] + (i < nc ? ue[size_t(a * nc + i)] : 0.0);
    }
  const auto keep = [&](Measure& m, double v, bool smallest) {
    const bool worse = smallest ? v < m.value : v > m.value;
    if (m.element < 0 || worse || (v == m.value && e.number < m.element)) m.value = v, m.element = e.number;
  };
  double smallest = std::numeric_limits<double>::infinity();
  for (const Point3& xi : checkedPoints(k)) {
    const double ref = jacobianDeterminant(t, X, xi);
    if (ref > 0) smallest = std::min(smallest, jacobianDeterminant(t, x, xi) / ref);
  }
  keep(detF, smallest, true);
  if (k.finiteKinematics()) return;
  IsoparametricPoint p;
  evaluateIsoparametric(t, X, centroid(t), p);
  double H[3][3] = {};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < nc; ++i)
      for (int j = 0; j < 3; ++j) H[i][j] += ue[size_t(a * nc + i)] * p.dNdx[size_t(a)][size_t(j)];
  if (k.kinematics() == Kinematics::Axisymmetric && p.x[0] > 0) {  // the hoop strain u_r / r
    double ur = 0.0;
    for (int a = 0; a < n; ++a) ur += p.N[size_t(a)] * ue[size_t(a * nc)];
    H[2][2] = ur / p.x[0];
  }
  double eps = 0.0, omega = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double s = 0.5 * (H[i][j] + H[j][i]), w = 0.5 * (H[i][j] - H[j][i]);
      eps += s * s, omega += 0.5 * w * w;  // |w| = the rotation vector's length: each pair counted twice
    }
  keep(strain, std::sqrt(eps), false);
  keep(rotation, std::sqrt(omega), false);
}

// The worst value over the ranks (the smallest or the largest) and the lowest element holding it.
FiniteStrainForce::Measure FiniteStrainForce::worstOverRanks(Measure local, bool smallest) const {
  const Comm& comm = *K0_->getComm();
  const double none = smallest ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  if (local.element < 0) local.value = none;
  Measure m;
  Teuchos::reduceAll<int, double>(comm, smallest ? Teuchos::REDUCE_MIN : Teuchos::REDUCE_MAX, local.value,
                                  Teuchos::outArg(m.value));
  const int mine = local.element >= 0 && local.value == m.value ? local.element : std::numeric_limits<int>::max();
  int first = mine;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  m.element = first == std::numeric_limits<int>::max() ? -1 : first;
  return m;
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
  detF = worstOverRanks(detF, true);
  strain = worstOverRanks(strain, false);
  rotation = worstOverRanks(rotation, false);
  ElementValidity v;
  if (detF.element >= 0 && !(detF.value > 0))
    v.failure = describeMeasure(detF, format("inverted: det F = %.4g at a corner or quadrature point (the element "
                                             "has turned inside out; a finer mesh, a smaller step or 'Formulation' = "
                                             "'F-bar' may hold it)", detF.value));
  if (!v.failure.empty()) return v;
  const double lim = ElementValidity::kSmallStrainLimit, warn = ElementValidity::kSmallStrainWarning;
  const bool strainWorse = strain.element >= 0 && strain.value / lim >= rotation.value / lim;
  const Measure& worst = strainWorse || rotation.element < 0 ? strain : rotation;
  if (worst.element < 0 || !(worst.value > warn)) return v;
  const std::string what = format(strainWorse ? "a small strain of %.3g (||sym grad u||)" : "a rotation of %.3g rad",
                                  worst.value);
  const std::string text =
      what + format(" is past the small-strain %s (%g)", worst.value > lim ? "limit" : "bound", worst.value > lim ? lim : warn) +
      ": set the block's 'Strain' = 'finite' (with a finite-strain material) for large strains and rotations";
  (worst.value > lim ? v.failure : v.warning) = describeMeasure(worst, text);
  return v;
}

}  // namespace choc
