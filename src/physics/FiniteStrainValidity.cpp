// FiniteStrainForce::validity: every element's det F at its corners and quadrature points, and
// the small-strain blocks' strain and rotation (ElementValidity.hpp).
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>
#include <utility>

#include "core/CollectiveFailure.hpp"
#include "core/Format.hpp"
#include "fem/ShapeFunctions.hpp"
#include "physics/FiniteStrainForce.hpp"

namespace choc {

namespace {

// The natural derivatives dN_a/dxi at the points an element is checked at (a one-point element's
// corners, then the quadrature points), and N, dN at its centre: one table per shape, rule and
// formulation, made once. A one-point element's force sees only its mean gradient, so its corners
// are checked too; the other elements' points are those their force integrates (a quadratic
// element's corner may turn slightly negative in a large deformation while its points, where it
// is integrated, stay positive).
struct PointTable {
  int dim = 3, nodes = 0, corners = 0;
  std::vector<Point3> xi;                // the checked points
  std::vector<std::vector<Point3>> dN;  // per checked point, per node
  std::vector<double> centreN;
  std::vector<Point3> centreDN;
};

const PointTable& pointTable(const FiniteStrainSolid& k) {
  static std::map<std::tuple<int, const QuadratureRule*, bool>, PointTable> tables;
  const SolidShape t = k.shape();
  PointTable& table = tables[{int(t), &k.rule(), k.onePoint()}];
  if (table.nodes > 0) return table;
  table.dim = parametricDimension(t), table.nodes = k.numNodes(), table.corners = cornerCount(t);
  const std::vector<Point3>& nodes = nodeNaturalCoordinates(t);
  if (k.onePoint()) table.xi.assign(nodes.begin(), nodes.begin() + table.corners);
  table.xi.insert(table.xi.end(), k.rule().points.begin(), k.rule().points.end());
  std::vector<double> N;
  for (const Point3& xi : table.xi) {
    table.dN.emplace_back();
    shapeFunctions(t, xi, N, table.dN.back());
  }
  Point3 centre{0, 0, 0};
  for (int a = 0; a < table.corners; ++a)
    for (int i = 0; i < 3; ++i) centre[size_t(i)] += nodes[size_t(a)][size_t(i)] / table.corners;
  shapeFunctions(t, centre, table.centreN, table.centreDN);
  return table;
}

// det J of the map of the nodes x at a point, J_ij = sum_a dN_a/dxi_i x_a,j (2 x 2 for planar shapes).
double determinant(const PointTable& t, const std::vector<Point3>& dN, const std::vector<Point3>& x, double J[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J[i][j] = 0.0;
  for (int a = 0; a < t.nodes; ++a)
    for (int i = 0; i < t.dim; ++i)
      for (int j = 0; j < t.dim; ++j) J[i][j] += dN[size_t(a)][size_t(i)] * x[size_t(a)][size_t(j)];
  if (t.dim == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

// The inverse of J (2 x 2 for planar shapes).
void invert(const PointTable& t, const double J[3][3], double Jinv[3][3]) {
  if (t.dim == 2) {
    const double d = J[0][0] * J[1][1] - J[0][1] * J[1][0];
    Jinv[0][0] = J[1][1] / d, Jinv[0][1] = -J[0][1] / d, Jinv[1][0] = -J[1][0] / d, Jinv[1][1] = J[0][0] / d;
    return;
  }
  const double d = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                   J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {  // the cofactor of J_ji over det J
      const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
      Jinv[i][j] = (J[r0][c0] * J[r1][c1] - J[r0][c1] * J[r1][c0]) / d;
    }
}

// The small strain ||sym H|| and the rotation |skew H| (the rotation vector's length) at the
// element's centre, H = du/dX (dN/dX = J(X)^-1 dN/dxi; axisymmetric: the hoop strain u_r / r).
std::pair<double, double> smallStrainAtCentre(const PointTable& t, const std::vector<Point3>& X,
                                              const std::vector<double>& ue, int nc, bool axisymmetric) {
  double J[3][3], Jinv[3][3] = {}, H[3][3] = {};
  determinant(t, t.centreDN, X, J);
  invert(t, J, Jinv);
  for (int a = 0; a < t.nodes; ++a) {
    double dNdX[3] = {0, 0, 0};
    for (int j = 0; j < t.dim; ++j)
      for (int i = 0; i < t.dim; ++i) dNdX[j] += Jinv[j][i] * t.centreDN[size_t(a)][size_t(i)];
    for (int i = 0; i < nc; ++i)
      for (int j = 0; j < t.dim; ++j) H[i][j] += ue[size_t(a * nc + i)] * dNdX[j];
  }
  if (axisymmetric) {
    double r = 0.0, ur = 0.0;
    for (int a = 0; a < t.nodes; ++a) r += t.centreN[size_t(a)] * X[size_t(a)][0], ur += t.centreN[size_t(a)] * ue[size_t(a * nc)];
    if (r > 0) H[2][2] = ur / r;
  }
  double eps = 0.0, omega = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double sym = 0.5 * (H[i][j] + H[j][i]), w = 0.5 * (H[i][j] - H[j][i]);
      eps += sym * sym, omega += 0.5 * w * w;  // each pair of the skew part counted twice
    }
  return {std::sqrt(eps), std::sqrt(omega)};
}

}  // namespace

// The smallest det F over the element's checked points where the deformed map's det J is not
// positive (+1 when it is positive everywhere: the reference map, checked at the start, is
// positive at every quadrature point and at a linear element's corners; a quadratic element's
// corner with det J(X) = 0, a quarter-point element's, is not judged); on a small-strain block
// also the strain and rotation at its centre. Each measure keeps the worst value and, on a tie,
// the lowest element.
void FiniteStrainForce::measureElement(const Element& e, const std::vector<double>& ue, Measure& detF,
                                       Measure& strain, Measure& rotation) const {
  const FiniteStrainSolid& k = *e.kernel;
  const PointTable& t = pointTable(k);
  const int n = t.nodes, nc = k.componentsPerNode();
  const double* X0 = reference_.data() + referenceAt_[size_t(&e - elements_.data())];
  thread_local std::vector<Point3> X, x;
  X.resize(size_t(n)), x.resize(size_t(n));
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      X[size_t(a)][size_t(i)] = X0[3 * a + i];
      x[size_t(a)][size_t(i)] = X0[3 * a + i] + (i < nc ? ue[size_t(a * nc + i)] : 0.0);
    }
  const auto keep = [&](Measure& m, double v, bool smallest) {
    const bool worse = smallest ? v < m.value : v > m.value;
    if (m.element < 0 || worse || (v == m.value && e.number < m.element)) m.value = v, m.element = e.number;
  };
  double J[3][3], smallest = 1.0;
  for (size_t p = 0; p < t.dN.size(); ++p) {
    const double current = determinant(t, t.dN[p], x, J);
    if (current > 0) continue;
    const double reference = determinant(t, t.dN[p], X, J);
    if (reference > 0) smallest = std::min(smallest, current / reference);
  }
  keep(detF, smallest, true);
  if (k.finiteKinematics()) return;
  const auto [eps, omega] = smallStrainAtCentre(t, X, ue, nc, k.kinematics() == Kinematics::Axisymmetric);
  keep(strain, eps, false);
  keep(rotation, omega, false);
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
    v.failure = describeMeasure(detF, format("inverted: det F = %.4g at a quadrature point or a one-point element's corner (the element "
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
