// Total Lagrangian continuum kernel (formulas in the header).
#include "fem/FiniteStrainSolid.hpp"

#include <algorithm>
#include <sstream>

#include "fem/IsoparametricPoint.hpp"
#include "fem/SolidGeometry.hpp"

namespace choc {

namespace {

// A component F_iJ that the kinematics lets vary, and the element component it varies with:
// dF_iJ = sum_a g_a du_a,comp, with g_a = dN_a/dX_J, or N_a / R for the hoop stretch.
struct GradientRow {
  int i, J, comp;
};

const std::vector<GradientRow>& gradientRows(Kinematics k) {
  static const std::vector<GradientRow> threeD = {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 1, 1},
                                                  {1, 2, 1}, {2, 0, 2}, {2, 1, 2}, {2, 2, 2}};
  static const std::vector<GradientRow> plane = {{0, 0, 0}, {0, 1, 0}, {1, 0, 1}, {1, 1, 1}};
  static const std::vector<GradientRow> axi = {{0, 0, 0}, {0, 1, 0}, {1, 0, 1}, {1, 1, 1}, {2, 2, 0}};
  return k == Kinematics::ThreeD ? threeD : (k == Kinematics::PlaneStrain ? plane : axi);
}

double rowValue(Kinematics k, const GradientRow& r, const IsoparametricPoint& p, int a) {
  if (k == Kinematics::Axisymmetric && r.J == 2) return p.N[size_t(a)] / p.x[0];
  return p.dNdx[size_t(a)][size_t(r.J)];
}

// The state at one quadrature point: F, the material's response to C = F^T F, and P = F S.
struct PointState {
  Mat3 F;
  StressResponse response;
  Mat3 P;
};

void evaluatePoint(Kinematics k, const HyperelasticMaterial& m, SolidShape t, const Point3& xi,
                   const IsoparametricPoint& p, const std::vector<double>& u, bool withTangent, PointState& s) {
  s.F = identity3();
  const int nc = k == Kinematics::ThreeD ? 3 : 2, n = static_cast<int>(p.N.size());
  for (const GradientRow& r : gradientRows(k))
    for (int a = 0; a < n; ++a) s.F[r.i][r.J] += rowValue(k, r, p, a) * u[size_t(a * nc + r.comp)];
  const double J = determinant(s.F);
  if (!(J > 0)) {
    std::ostringstream msg;
    msg << "inverted " << topologyName(t) << " element: det F = " << J << " <= 0 at natural point "
        << naturalPointText(t, xi);
    throw InvertedElement(msg.str());
  }
  try {
    m.respond(transposeTimes(s.F), withTangent, s.response);
  } catch (const std::domain_error& e) {
    throw InvertedElement(std::string(topologyName(t)) + " element at natural point " + naturalPointText(t, xi) +
                          ": " + e.what());
  }
  s.P = multiply(s.F, s.response.S);
}

// A_rs = dP_r / dF_s for the kinematics' rows: delta_ik S_JL + F_iI F_kK CC_IJKL.
void firstElasticity(Kinematics k, const PointState& s, std::vector<double>& A) {
  const auto& rows = gradientRows(k);
  const size_t nr = rows.size();
  A.assign(nr * nr, 0.0);
  const auto& C = s.response.tangent;
  for (size_t r = 0; r < nr; ++r)
    for (size_t q = 0; q < nr; ++q) {
      const int i = rows[r].i, J = rows[r].J, kk = rows[q].i, L = rows[q].J;
      double v = i == kk ? s.response.S[J][L] : 0.0;
      for (int I = 0; I < 3; ++I) {
        if (s.F[i][I] == 0.0) continue;
        for (int K = 0; K < 3; ++K) v += s.F[i][I] * s.F[kk][K] * C[I][J][K][L];
      }
      A[r * nr + q] = v;
    }
}

// K += w G^T A G with G the gradient rows' values at p.
void addTangent(Kinematics k, const IsoparametricPoint& p, const std::vector<double>& A, double w, DenseMatrix& K) {
  const auto& rows = gradientRows(k);
  const int nr = static_cast<int>(rows.size()), n = static_cast<int>(p.N.size());
  const int nc = k == Kinematics::ThreeD ? 3 : 2, nd = n * nc;
  std::vector<double> g(size_t(nr) * n), AG(static_cast<size_t>(nd));
  for (int r = 0; r < nr; ++r)
    for (int a = 0; a < n; ++a) g[size_t(r) * n + a] = rowValue(k, rows[size_t(r)], p, a);
  for (int r = 0; r < nr; ++r) {
    std::fill(AG.begin(), AG.end(), 0.0);
    for (int q = 0; q < nr; ++q) {
      const double a = A[size_t(r) * nr + q];
      if (a == 0.0) continue;
      for (int b = 0; b < n; ++b) AG[size_t(b * nc + rows[size_t(q)].comp)] += a * g[size_t(q) * n + b];
    }
    for (int a = 0; a < n; ++a) {
      const double ga = w * g[size_t(r) * n + a];
      if (ga == 0.0) continue;
      const int row = a * nc + rows[size_t(r)].comp;
      for (int j = 0; j < nd; ++j) K(row, j) += ga * AG[size_t(j)];
    }
  }
}

}  // namespace

FiniteStrainSolid::FiniteStrainSolid(const std::string& topology, Kinematics kinematics,
                                     std::shared_ptr<const HyperelasticMaterial> material)
    : shape_(solidTopology(topology)), kin_(kinematics), material_(std::move(material)) {
  checkSolidKinematics(shape_, kin_);
}

double FiniteStrainSolid::evaluate(const std::vector<Point3>& X, const std::vector<double>& u,
                                   std::vector<double>& f, DenseMatrix* K) const {
  validateSolidNodes(shape_, kin_, X);
  const QuadratureRule& rule = stiffnessRule(shape_, kin_);
  const int nc = componentsPerNode(), n = numNodes(), nd = n * nc;
  f.assign(size_t(nd), 0.0);
  if (K) K->resize(nd, nd);
  IsoparametricPoint p;
  PointState s;
  std::vector<double> A;
  double energy = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    const double w = solidVolumeWeight(shape_, kin_, X, rule, q, p);
    evaluatePoint(kin_, *material_, shape_, rule.points[size_t(q)], p, u, K != nullptr, s);
    energy += w * s.response.energy;
    for (const GradientRow& r : gradientRows(kin_))
      for (int a = 0; a < n; ++a) f[size_t(a * nc + r.comp)] += w * s.P[r.i][r.J] * rowValue(kin_, r, p, a);
    if (!K) continue;
    firstElasticity(kin_, s, A);
    addTangent(kin_, p, A, w, *K);
  }
  return energy;
}

void FiniteStrainSolid::averageStress(const std::vector<Point3>& X, const std::vector<double>& u,
                                      std::array<double, 6>& sigma, double& energyDensity) const {
  validateSolidNodes(shape_, kin_, X);
  const QuadratureRule& rule = stiffnessRule(shape_, kin_);
  IsoparametricPoint p;
  PointState s;
  sigma.fill(0.0);
  energyDensity = 0.0;
  double volume = 0.0;
  for (int q = 0; q < rule.size(); ++q) {
    const double w = solidVolumeWeight(shape_, kin_, X, rule, q, p);
    evaluatePoint(kin_, *material_, shape_, rule.points[size_t(q)], p, u, false, s);
    const Mat3 c = cauchyStress(s.F, s.response.S);
    const double v[6] = {c[0][0], c[1][1], c[2][2], c[0][1], c[1][2], c[2][0]};
    for (int i = 0; i < 6; ++i) sigma[size_t(i)] += w * v[i];
    energyDensity += w * s.response.energy;
    volume += w;
  }
  for (double& v : sigma) v /= volume;
  energyDensity /= volume;
}

}  // namespace choc
