// Total Lagrangian continuum kernel (formulas in the header).
#include "fem/FiniteStrainSolid.hpp"

#include <algorithm>
#include <optional>
#include <sstream>
#include <type_traits>

#include "fem/FBarTangent.hpp"
#include "fem/IsoparametricPoint.hpp"
#include "fem/SolidGeometry.hpp"
#include "materials/HyperelasticPoint.hpp"
#include "materials/J2Point.hpp"

namespace choc {

// One quadrature point of an ElementGeometry.
struct PointView {
  int nodes;
  const double* dNdX;  // [a 3 + J]
  const double* N;     // axisymmetric only
  double R;
};

// The state at one quadrature point: F and the material's response to it (and to the point's
// committed state).
struct PointState {
  Mat3 F;                  // the material's F: F-bar's (J0 / J)^(1/3) F, else F
  Mat3 Fstd;               // the point's own F = I + du/dX
  double ratio = 1.0;      // (J0 / J)^(1/3) with F-bar, else 1
  PointResponse response;  // P, dP/dF, W
};

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

PointView pointOf(const ElementGeometry& g, int q) {
  const bool axi = !g.radius.empty();
  return {g.nodes, &g.dNdX[size_t(q) * g.nodes * 3], axi ? &g.N[size_t(q) * g.nodes] : nullptr,
          axi ? g.radius[size_t(q)] : 0.0};
}

double rowValue(Kinematics k, const GradientRow& r, const PointView& p, int a) {
  if (k == Kinematics::Axisymmetric && r.J == 2) return p.N[a] / p.R;
  return p.dNdX[a * 3 + r.J];
}

// The common node counts with the count known to the compiler (its loops unrolled, the sums in
// registers), any other through the run-time count (N = 0): the same terms in the same order.
template <class Kernel>
void byNodeCount(int nodes, Kernel&& kernel) {
  switch (nodes) {
    case 4: return kernel(std::integral_constant<int, 4>{});
    case 8: return kernel(std::integral_constant<int, 8>{});
    case 10: return kernel(std::integral_constant<int, 10>{});
    case 20: return kernel(std::integral_constant<int, 20>{});
    default: return kernel(std::integral_constant<int, 0>{});
  }
}

// 3D: G_iJ = sum_a u_a,i dN_a/dX_J, every row in one pass over the nodes.
template <int N>
void displacementGradient3D(int nodes, const double* __restrict dNdX, const double* __restrict u, double G[3][3]) {
  const int n = N ? N : nodes;
  double s[3][3] = {};
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) s[i][J] += dNdX[a * 3 + J] * u[a * 3 + i];
  for (int i = 0; i < 3; ++i)
    for (int J = 0; J < 3; ++J) G[i][J] = s[i][J];
}

Mat3 deformationGradient(Kinematics k, const PointView& p, const std::vector<double>& u) {
  Mat3 F = identity3();
  if (k == Kinematics::ThreeD) {  // every row, one pass over the nodes (the same sums, in the same order)
    double G[3][3];
    byNodeCount(p.nodes, [&](auto N) { displacementGradient3D<decltype(N)::value>(p.nodes, p.dNdX, u.data(), G); });
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) F[i][J] += G[i][J];
    return F;
  }
  const int nc = 2;
  for (const GradientRow& r : gradientRows(k)) {
    double v = 0.0;
    for (int a = 0; a < p.nodes; ++a) v += rowValue(k, r, p, a) * u[size_t(a * nc + r.comp)];
    F[r.i][r.J] += v;
  }
  return F;
}

// 3D: f_a,i += sum_J s_iJ dN_a/dX_J.
template <int N>
void addNodalForces3D(int nodes, const double* __restrict dNdX, const double (&s)[3][3], double* __restrict f) {
  const int n = N ? N : nodes;
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < 3; ++i) {
      double v = f[a * 3 + i];
      for (int J = 0; J < 3; ++J) v += s[i][J] * dNdX[a * 3 + J];
      f[a * 3 + i] = v;
    }
}

// f_a,comp += stress(i, J) g_a,iJ over the kinematics' rows (in 3D each node's three components
// in one pass: every f entry receives the same terms in the same order as row by row).
template <class Stress>
void addPointForce(Kinematics k, const PointView& p, Stress stress, std::vector<double>& f) {
  if (k == Kinematics::ThreeD) {
    double s[3][3];
    for (int i = 0; i < 3; ++i)
      for (int J = 0; J < 3; ++J) s[i][J] = stress(i, J);
    byNodeCount(p.nodes, [&](auto N) { addNodalForces3D<decltype(N)::value>(p.nodes, p.dNdX, s, f.data()); });
    return;
  }
  const int nc = 2;
  for (const GradientRow& r : gradientRows(k)) {
    const double v = stress(r.i, r.J);
    for (int a = 0; a < p.nodes; ++a) f[size_t(a * nc + r.comp)] += v * rowValue(k, r, p, a);
  }
}

// J0 > 0: F-bar, the material gets (J0 / J)^(1/3) F (J0 the element's mean dilatation). The
// material's new state into `next` when not null.
void evaluatePoint(const MaterialPoint& m, SolidShape t, const Point3& xi, const Mat3& F, const double* old,
                   double* next, const PointRequest& request, PointState& s, double J0 = 0.0) {
  s.Fstd = s.F = F;
  const double J = determinant(s.F);
  if (m.finiteStrain() && !(J > 0)) {
    std::ostringstream msg;
    msg << "inverted " << topologyName(t) << " element: det F = " << J << " <= 0 at natural point "
        << naturalPointText(t, xi);
    throw InvertedElement(msg.str());
  }
  s.ratio = 1.0;
  if (J0 > 0) {
    s.ratio = std::cbrt(J0 / J);
    for (auto& row : s.F)
      for (double& v : row) v *= s.ratio;
  }
  try {
    m.respond(s.F, old, next, request, s.response);
  } catch (const std::domain_error& e) {
    throw InvertedElement(std::string(topologyName(t)) + " element at natural point " + naturalPointText(t, xi) +
                          ": " + e.what());
  }
}

// A_rs = dP_r / dF_s for the kinematics' rows, from the material's full dP/dF.
void firstElasticity(Kinematics k, const PointState& s, std::vector<double>& A) {
  const auto& rows = gradientRows(k);
  const size_t nr = rows.size();
  A.assign(nr * nr, 0.0);
  for (size_t r = 0; r < nr; ++r)
    for (size_t q = 0; q < nr; ++q)
      A[r * nr + q] = s.response.A[3 * rows[r].i + rows[r].J][3 * rows[q].i + rows[q].J];
}

// K += w G^T A G with G the gradient rows' values at p.
void addTangent(Kinematics k, const PointView& p, const std::vector<double>& A, double w, DenseMatrix& K) {
  const auto& rows = gradientRows(k);
  const int nr = static_cast<int>(rows.size()), n = p.nodes;
  const int nc = k == Kinematics::ThreeD ? 3 : 2, nd = n * nc;
  thread_local std::vector<double> g, AG;
  g.resize(size_t(nr) * n);
  AG.resize(static_cast<size_t>(nd));
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
      for (int j = row; j < nd; ++j) K(row, j) += ga * AG[size_t(j)];  // the upper triangle (mirrored once)
    }
  }
}

}  // namespace

FiniteStrainSolid::FiniteStrainSolid(const std::string& topology, Kinematics kinematics,
                                     std::shared_ptr<const HyperelasticMaterial> material, bool fbar)
    : FiniteStrainSolid(topology, kinematics, hyperelasticPoint(std::move(material)), ElementFormulation{fbar}) {}

FiniteStrainSolid::FiniteStrainSolid(const std::string& topology, Kinematics kinematics,
                                     std::shared_ptr<const J2Plasticity> material, bool fbar)
    : FiniteStrainSolid(topology, kinematics, j2Point(std::move(material)), ElementFormulation{fbar}) {}

FiniteStrainSolid::FiniteStrainSolid(const std::string& topology, Kinematics kinematics,
                                     std::shared_ptr<const MaterialPoint> material,
                                     const ElementFormulation& formulation)
    : shape_(solidTopology(topology)),
      kin_(kinematics),
      material_(std::move(material)),
      fbar_(formulation.fbar),
      onePoint_(formulation.onePoint),
      hourglass_(formulation.hourglass) {
  checkSolidKinematics(shape_, kin_);
  checkFormulation();
  fields_ = material_->fieldNames().size();
  rule_ = onePoint_ ? &gaussBoxRule(parametricDimension(shape_), 1) : &stiffnessRule(shape_, kin_);
}

void FiniteStrainSolid::checkFormulation() const {
  if (fbar_ && onePoint_) throw std::invalid_argument("F-bar and one-point integration exclude each other");
  if (onePoint_ && !((shape_ == SolidShape::Hex8 && kin_ == Kinematics::ThreeD) ||
                     (shape_ == SolidShape::Quad4 && kin_ == Kinematics::PlaneStrain)))
    throw std::invalid_argument(std::string("one-point integration with hourglass control is for HEX8 in 3D and QUAD4 "
                                            "in plane strain, not ") +
                                topologyName(shape_) +
                                (kin_ == Kinematics::Axisymmetric ? " (axisymmetric)" : ""));
  if (onePoint_ && !(hourglass_ > 0 && hourglass_ <= 1))
    throw std::invalid_argument("the hourglass coefficient must lie in (0, 1]");
  if (!fbar_) return;
  if (shape_ == SolidShape::Tet4 || shape_ == SolidShape::Tri3)
    throw std::invalid_argument(std::string("F-bar averages the volume change over an element's points; ") +
                                topologyName(shape_) + " has one (use " +
                                (shape_ == SolidShape::Tet4 ? "TET10" : "TRI6") + " with F-bar for plastic flow)");
  if (!finiteKinematics()) throw std::invalid_argument("F-bar needs finite-strain kinematics ('Strain' = 'finite')");
}


int FiniteStrainSolid::stateSize() const {
  return material_->stateSize() * rule().size();
}

void FiniteStrainSolid::initialState(double* state) const {
  const int n = material_->stateSize();
  for (int q = 0; q < rule().size() && n > 0; ++q) material_->initialState(state + n * q);
}

double FiniteStrainSolid::modulus() const {
  return material_->modulus();
}

ElementGeometry FiniteStrainSolid::geometry(const std::vector<Point3>& X) const {
  validateSolidNodes(shape_, kin_, X);
  const QuadratureRule& rule = stiffnessRule(shape_, kin_);
  ElementGeometry g;
  g.points = rule.size();
  g.nodes = numNodes();
  const bool axi = kin_ == Kinematics::Axisymmetric;
  IsoparametricPoint p;
  for (int q = 0; q < rule.size(); ++q) {
    g.weight.push_back(solidVolumeWeight(shape_, kin_, X, rule, q, p));
    for (int a = 0; a < g.nodes; ++a)
      for (int J = 0; J < 3; ++J) g.dNdX.push_back(p.dNdx[size_t(a)][size_t(J)]);
    if (!axi) continue;
    g.N.insert(g.N.end(), p.N.begin(), p.N.end());
    g.radius.push_back(p.x[0]);
  }
  if (onePoint_) condenseToOnePoint(X, g);
  return g;
}

void FiniteStrainSolid::condenseToOnePoint(const std::vector<Point3>& X, ElementGeometry& g) const {
  const int n = g.nodes, dim = parametricDimension(shape_);
  double V = 0.0;
  std::vector<double> b(size_t(n) * 3, 0.0);
  for (int q = 0; q < g.points; ++q) {
    const double w = g.weight[size_t(q)];
    V += w;
    for (size_t k = 0; k < b.size(); ++k) b[k] += w * g.dNdX[size_t(q) * b.size() + k];
  }
  double bb = 0.0;
  for (double& v : b) v /= V, bb += v * v;
  g.points = 1;
  g.weight.assign(1, V);
  g.dNdX = b;
  // The hourglass base vectors: the products of two or three natural coordinates at the nodes.
  const auto& xi = nodeNaturalCoordinates(shape_);
  std::vector<std::vector<double>> Gamma;
  if (dim == 3) {
    for (int m = 0; m < 4; ++m) {
      Gamma.emplace_back();
      for (int a = 0; a < n; ++a) {
        const Point3& c = xi[size_t(a)];
        Gamma.back().push_back(m == 0 ? c[1] * c[2] : m == 1 ? c[2] * c[0] : m == 2 ? c[0] * c[1] : c[0] * c[1] * c[2]);
      }
    }
  } else {
    Gamma.emplace_back();
    for (int a = 0; a < n; ++a) Gamma.back().push_back(xi[size_t(a)][0] * xi[size_t(a)][1]);
  }
  g.hourglass.clear();
  for (const auto& G : Gamma) {
    double GX[3] = {0, 0, 0};  // Gamma . X_J
    for (int a = 0; a < n; ++a)
      for (int J = 0; J < dim; ++J) GX[J] += G[size_t(a)] * X[size_t(a)][size_t(J)];
    for (int a = 0; a < n; ++a) {
      double v = G[size_t(a)];
      for (int J = 0; J < dim; ++J) v -= GX[J] * b[size_t(a) * 3 + size_t(J)];
      g.hourglass.push_back(v);
    }
  }
  g.hourglassStiffness = hourglass_ * modulus() * V * bb / (dim == 3 ? 72.0 : 24.0);
}

// Mode m's amplitudes q_m,i = sum_a gamma_m,a u_a,i (i < nc).
static void hourglassAmplitude(const ElementGeometry& g, int m, int nc, const std::vector<double>& u, double q[3]) {
  const double* gm = &g.hourglass[size_t(m) * g.nodes];
  q[0] = q[1] = q[2] = 0.0;
  for (int a = 0; a < g.nodes; ++a)
    for (int i = 0; i < nc; ++i) q[i] += gm[a] * u[size_t(a * nc + i)];
}

double FiniteStrainSolid::hourglassEnergy(const ElementGeometry& g, const std::vector<double>& u) const {
  const int nc = componentsPerNode(), modes = g.nodes ? static_cast<int>(g.hourglass.size()) / g.nodes : 0;
  double energy = 0.0, q[3];
  for (int m = 0; m < modes; ++m) {
    hourglassAmplitude(g, m, nc, u, q);
    for (int i = 0; i < nc; ++i) energy += 0.5 * g.hourglassStiffness * q[i] * q[i];
  }
  return energy;
}

namespace {

// The hourglass energy and force k gamma_m,a q_m,i of M modes on N nodes of NC components: every
// mode's amplitudes in one pass over the nodes, then each node's force from the modes in order.
// Sizes of 0 are taken at run time (n, nc, modes; at most 4 modes of 3 components).
template <int N, int NC, int M>
double hourglassForce(int n, int nc, int modes, const double* __restrict gamma, double k, const double* __restrict u,
                      double* __restrict f) {
  n = N ? N : n, nc = NC ? NC : nc, modes = M ? M : modes;
  double q[4][3] = {};
  for (int a = 0; a < n; ++a)
    for (int m = 0; m < modes; ++m)
      for (int i = 0; i < nc; ++i) q[m][i] += gamma[m * n + a] * u[a * nc + i];
  double energy = 0.0;
  for (int m = 0; m < modes; ++m)
    for (int i = 0; i < nc; ++i) energy += 0.5 * k * q[m][i] * q[m][i];
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < nc; ++i) {
      double v = f[a * nc + i];
      for (int m = 0; m < modes; ++m) v += k * gamma[m * n + a] * q[m][i];
      f[a * nc + i] = v;
    }
  return energy;
}

}  // namespace

double FiniteStrainSolid::addHourglass(const ElementGeometry& g, const std::vector<double>& u, std::vector<double>& f,
                                       DenseMatrix* K) const {
  const int n = g.nodes, nc = componentsPerNode(), modes = static_cast<int>(g.hourglass.size()) / n;
  const double k = g.hourglassStiffness;
  const double energy = n == 8 && nc == 3 && modes == 4  // HEX8 in 3D; QUAD4 in plane strain (1 mode) at run time
                            ? hourglassForce<8, 3, 4>(n, nc, modes, g.hourglass.data(), k, u.data(), f.data())
                            : hourglassForce<0, 0, 0>(n, nc, modes, g.hourglass.data(), k, u.data(), f.data());
  for (int m = 0; m < modes && K; ++m) {
    const double* gm = &g.hourglass[size_t(m) * n];
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int i = 0; i < nc; ++i) (*K)(a * nc + i, b * nc + i) += k * gm[a] * gm[b];
  }
  return energy;
}

// F-bar's mean dilatation: Jbar = int J dV / V, and dJbar/du_a / Jbar (header) into B.
double FiniteStrainSolid::meanDilatation(const ElementGeometry& g, const std::vector<Mat3>& Fq, std::vector<double>& B,
                                         std::vector<Mat3>& Finv) const {
  if (!fbar_) return 0.0;
  const int nc = componentsPerNode();
  B.assign(size_t(g.nodes * nc), 0.0);
  Finv.resize(size_t(g.points));
  double V = 0.0, JV = 0.0;
  for (int q = 0; q < g.points; ++q) {
    const PointView p = pointOf(g, q);
    const Mat3& F = Fq[size_t(q)];
    const double J = determinant(F), w = g.weight[size_t(q)];
    if (!(J > 0)) {
      std::ostringstream msg;
      msg << "inverted " << topologyName(shape_) << " element: det F = " << J << " <= 0 at a quadrature point";
      throw InvertedElement(msg.str());
    }
    const Mat3& Fi = Finv[size_t(q)] = inverse(F, J);
    V += w;
    JV += w * J;
    if (kin_ == Kinematics::ThreeD) {  // the rows' terms of each entry in the same order, one pass
      for (int a = 0; a < g.nodes; ++a) {
        const double* ga = p.dNdX + a * 3;
        for (int i = 0; i < 3; ++i)
          for (int Jc = 0; Jc < 3; ++Jc) B[size_t(a * 3 + i)] += w * J * Fi[Jc][i] * ga[Jc];
      }
      continue;
    }
    for (const GradientRow& r : gradientRows(kin_))
      for (int a = 0; a < g.nodes; ++a) B[size_t(a * nc + r.comp)] += w * J * Fi[r.J][r.i] * rowValue(kin_, r, p, a);
  }
  for (double& v : B) v /= JV;
  return JV / V;
}

// F-bar's force at one point: with Fbar = (Jbar / J)^(1/3) F and P = P(Fbar),
//   f_a,i += w [ (Jbar / J)^(1/3) P_iJ g_a,iJ - (P : Fbar) / 3 F^-1_Ji g_a,iJ ] + w (P : Fbar) / 3 B_a,i,
// the derivative of int W(Fbar) dV (d ln J = F^-T : dF; B = d ln Jbar / du).
void FiniteStrainSolid::addFBarForce(const PointView& p, const PointState& s, const Mat3& Finv,
                                     const std::vector<double>& B, double w, std::vector<double>& f) const {
  const double third = contract(s.response.P, s.F) / 3;
  addPointForce(kin_, p, [&](int i, int J) { return w * (s.ratio * s.response.P[i][J] - third * Finv[J][i]); }, f);
  for (size_t k = 0; k < f.size(); ++k) f[k] += w * third * B[k];
}

double FiniteStrainSolid::evaluate(const ElementGeometry& g, const std::vector<double>& u, std::vector<double>& f,
                                   DenseMatrix* K, const double* old, double* next, double* plasticWork,
                                   bool elasticTangent, double dt, double* hourglassEnergy) const {
  const QuadratureRule& rule = this->rule();
  const int nc = componentsPerNode(), n = g.nodes, nd = n * nc;
  f.assign(size_t(nd), 0.0);
  if (K) K->resize(nd, nd);
  // Reused from element to element: every field a point reads is written by evaluatePoint first
  // (a fresh one per element zeroed 2 kB of tangents the explicit force never reads).
  thread_local PointState s;
  thread_local std::vector<double> A;
  double energy = 0.0;
  thread_local std::vector<double> B;
  thread_local std::vector<Mat3> F, Finv;
  F.resize(size_t(g.points));
  for (int q = 0; q < g.points; ++q) F[size_t(q)] = deformationGradient(kin_, pointOf(g, q), u);
  const double J0 = meanDilatation(g, F, B, Finv);
  std::optional<FBarTangent> fbarTangent;
  if (fbar_ && K && !elasticTangent) {
    double V = 0.0;
    for (double w : g.weight) V += w;
    fbarTangent.emplace(nd, B, J0 * V);
  }
  const int ns = material_->stateSize();
  const PointRequest request{K != nullptr, elasticTangent, dt};
  for (int q = 0; q < g.points; ++q) {
    const double w = g.weight[size_t(q)];
    const PointView p = pointOf(g, q);
    evaluatePoint(*material_, shape_, rule.points[size_t(q)], F[size_t(q)], old ? old + ns * q : nullptr,
                  next ? next + ns * q : nullptr, request, s, J0);
    energy += w * s.response.energy;
    if (plastic() && plasticWork) *plasticWork += w * s.response.dissipated;
    if (fbar_)
      addFBarForce(p, s, Finv[size_t(q)], B, w, f);
    else
      addPointForce(kin_, p, [&](int i, int J) { return w * s.response.P[i][J]; }, f);
    if (!K) continue;
    if (fbarTangent) {
      addFBarTangent(p, s, F[size_t(q)], Finv[size_t(q)], w, *fbarTangent, *K);
      continue;
    }
    firstElasticity(kin_, s, A);
    addTangent(kin_, p, A, w, *K);
  }
  if (fbarTangent)
    fbarTangent->finish(*K);
  else if (K)  // every material's dP/dF has the major symmetry, so K = sum w G^T A G is symmetric (a
               // material without it would fail its element's central-difference tangent tests)
    for (int i = 0; i < nd; ++i)
      for (int j = 0; j < i; ++j) (*K)(i, j) = (*K)(j, i);
  if (onePoint_) {
    const double hg = addHourglass(g, u, f, K);
    energy += hg;
    if (hourglassEnergy) *hourglassEnergy = hg;
  }
  return energy;
}

// One point's terms of F-bar's consistent tangent: dF/du per DOF and the full dP/dFbar (the
// out-of-plane Fbar_zz = s varies in plane strain too).
void FiniteStrainSolid::addFBarTangent(const PointView& p, const PointState& s, const Mat3& F, const Mat3& Finv,
                                       double w, FBarTangent& tangent, DenseMatrix& K) const {
  const int nc = componentsPerNode();
  thread_local std::vector<double> G;
  G.assign(size_t(p.nodes * nc) * 9, 0.0);
  for (const GradientRow& r : gradientRows(kin_))
    for (int a = 0; a < p.nodes; ++a) G[size_t(a * nc + r.comp) * 9 + size_t(3 * r.i + r.J)] += rowValue(kin_, r, p, a);
  tangent.addPoint(G, F, Finv, determinant(F), s.F, s.ratio, s.response.P, s.response.A, w, K);
}

void FiniteStrainSolid::averageStress(const ElementGeometry& g, const std::vector<double>& u,
                                      std::array<double, 6>& sigma, double& energyDensity, const double* old,
                                      std::vector<double>* fields) const {
  const QuadratureRule& rule = this->rule();
  const MaterialPoint& m = *material_;
  const bool recorded = m.reportsState();  // the state's stress and energy, not u's
  PointState s;
  std::vector<double> B;
  std::vector<Mat3> F, Finv;
  if (!recorded)
    for (int q = 0; q < g.points; ++q) F.push_back(deformationGradient(kin_, pointOf(g, q), u));
  const double J0 = recorded ? 0.0 : meanDilatation(g, F, B, Finv);
  std::vector<double> virgin;
  if (m.stateSize() > 0 && !old) virgin.resize(size_t(stateSize())), initialState(virgin.data()), old = virgin.data();
  if (fields) fields->assign(fields_, 0.0);
  sigma.fill(0.0);
  energyDensity = 0.0;
  double volume = 0.0;
  for (int q = 0; q < g.points; ++q) {
    const double w = g.weight[size_t(q)];
    const double* st = old ? old + m.stateSize() * q : nullptr;
    Mat3 c;
    if (recorded) {  // the stress the last accepted increment ended at, from the point's state
      c = m.recordedCauchy(st);
      energyDensity += w * m.recordedEnergy(st);
    } else {
      evaluatePoint(m, shape_, rule.points[size_t(q)], F[size_t(q)], st, nullptr, PointRequest{}, s, J0);
      c = cauchyFromFirstPiola(s.response.P, s.F, m.finiteStrain());
      energyDensity += w * s.response.energy;
    }
    if (fields) m.addFields(st, c, w, fields->data());
    const double v[6] = {c[0][0], c[1][1], c[2][2], c[0][1], c[1][2], c[2][0]};
    for (int i = 0; i < 6; ++i) sigma[size_t(i)] += w * v[i];
    volume += w;
  }
  for (double& v : sigma) v /= volume;
  energyDensity /= volume;
  if (fields)
    for (double& v : *fields) v /= volume;
}

int FiniteStrainSolid::pointsAtMelting(const double* state) const {
  if (!thermal()) return 0;
  int n = 0;
  for (int q = 0; q < rule().size(); ++q) n += material_->melted(state + material_->stateSize() * q);
  return n;
}

double FiniteStrainSolid::largestDamage(const double* state) const {
  double d = 0.0;
  if (!damaged()) return d;
  for (int q = 0; q < rule().size(); ++q) d = std::max(d, material_->damage(state + material_->stateSize() * q));
  return d;
}

}  // namespace choc
