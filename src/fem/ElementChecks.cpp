#include "fem/ElementChecks.hpp"

#include <Teuchos_CommHelpers.hpp>

#include <cmath>
#include <limits>
#include <map>
#include <tuple>

#include "core/Format.hpp"
#include "fem/ElementValidity.hpp"

namespace choc {


const CheckPoints& checkPoints(SolidShape t, const QuadratureRule& rule, bool corners) {
  static std::map<std::tuple<int, const QuadratureRule*, bool>, CheckPoints> tables;
  CheckPoints& table = tables[{int(t), &rule, corners}];
  if (table.nodes > 0) return table;
  table.dim = parametricDimension(t), table.nodes = nodeCount(t), table.corners = cornerCount(t);
  const std::vector<Point3>& nodes = nodeNaturalCoordinates(t);
  if (corners) table.xi.assign(nodes.begin(), nodes.begin() + table.corners);
  table.xi.insert(table.xi.end(), rule.points.begin(), rule.points.end());
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
double mapDeterminant(const CheckPoints& t, const std::vector<Point3>& dN, const std::vector<Point3>& x, double J[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) J[i][j] = 0.0;
  for (int a = 0; a < t.nodes; ++a)
    for (int i = 0; i < t.dim; ++i)
      for (int j = 0; j < t.dim; ++j) J[i][j] += dN[size_t(a)][size_t(i)] * x[size_t(a)][size_t(j)];
  if (t.dim == 2) return J[0][0] * J[1][1] - J[0][1] * J[1][0];
  return J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) - J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
         J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
}

namespace {

// The inverse of J (2 x 2 for planar shapes).
void invert(const CheckPoints& t, const double J[3][3], double Jinv[3][3]) {
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

}  // namespace

// The small strain ||sym H|| and the rotation |skew H| (the rotation vector's length) at the
// element's centre, H = du/dX (dN/dX = J(X)^-1 dN/dxi; axisymmetric: the hoop strain u_r / r).
std::pair<double, double> smallStrainAtCentre(const CheckPoints& t, const std::vector<Point3>& X,
                                              const std::vector<double>& ue, int nc, bool axisymmetric) {
  double J[3][3], Jinv[3][3] = {}, H[3][3] = {};
  mapDeterminant(t, t.centreDN, X, J);
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


void keepWorst(ElementMeasure& m, double v, int element, bool smallest) {
  const bool worse = smallest ? v < m.value : v > m.value;
  if (m.element < 0 || worse || (v == m.value && element < m.element)) m.value = v, m.element = element;
}

ElementMeasure worstOverRanks(const Comm& comm, ElementMeasure local, bool smallest) {
  const double none = smallest ? std::numeric_limits<double>::infinity() : -std::numeric_limits<double>::infinity();
  if (local.element < 0) local.value = none;
  ElementMeasure m;
  Teuchos::reduceAll<int, double>(comm, smallest ? Teuchos::REDUCE_MIN : Teuchos::REDUCE_MAX, local.value,
                                  Teuchos::outArg(m.value));
  const int mine = local.element >= 0 && local.value == m.value ? local.element : std::numeric_limits<int>::max();
  int first = mine;
  Teuchos::reduceAll<int, int>(comm, Teuchos::REDUCE_MIN, mine, Teuchos::outArg(first));
  m.element = first == std::numeric_limits<int>::max() ? -1 : first;
  return m;
}

SmallStrainVerdict smallStrainVerdict(double strain, bool hasStrain, double rotation, bool hasRotation) {
  SmallStrainVerdict v;
  const double lim = ElementValidity::kSmallStrainLimit, warn = ElementValidity::kSmallStrainWarning;
  v.strain = hasStrain && (!hasRotation || strain >= rotation);
  const double worst = v.strain ? strain : rotation;
  if ((!hasStrain && !hasRotation) || !(worst > warn)) return v;
  v.failed = worst > lim;
  v.text = format(v.strain ? "a small strain of %.4g (||sym grad u||)" : "a rotation of %.4g rad", worst) +
           format(" is past the small-strain %s (%g)", v.failed ? "limit" : "bound", v.failed ? lim : warn) +
           ": set the block's 'Strain' = 'finite' (with a finite-strain material) for large strains and rotations";
  return v;
}

}  // namespace choc
