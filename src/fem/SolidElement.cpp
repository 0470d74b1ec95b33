// Isoparametric continuum kernel: K = sum_q w_q B^T D B dV_q, m_ab = sum_q w_q rho N_a N_b dV_q
// with dV_q = det J (times 2 pi r when axisymmetric).
#include "fem/SolidElement.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fem/Components.hpp"
#include "fem/IsoparametricPoint.hpp"
#include "fem/MassLumping.hpp"
#include "fem/SolidGeometry.hpp"
#include "fem/ShapeFunctions.hpp"

namespace choc {

namespace {

void checkMaterial(SolidShape t, const Material& m) {
  auto fail = [t](const char* what, double value) {
    std::ostringstream msg;
    msg << topologyName(t) << " element: " << what << ", got " << value;
    throw std::invalid_argument(msg.str());
  };
  if (!(m.youngsModulus > 0)) fail("Young's modulus must be > 0", m.youngsModulus);
  if (!(m.poissonsRatio > -1.0 && m.poissonsRatio < 0.5))
    fail("Poisson ratio must be in (-1, 0.5)", m.poissonsRatio);
  if (!(m.density >= 0)) fail("density must be >= 0", m.density);
}

// Strain-displacement matrix B (strains x element DOFs). Strain order: ThreeD (xx, yy, zz,
// 2xy, 2yz, 2zx); PlaneStrain (xx, yy, 2xy); Axisymmetric (rr, zz, thetatheta, 2rz). The
// normal strains come first, then the engineering shear strains.
void strainDisplacement(Kinematics k, const IsoparametricPoint& p, DenseMatrix& B) {
  const int n = static_cast<int>(p.N.size());
  if (k == Kinematics::ThreeD) {
    B.resize(6, 3 * n);
    for (int a = 0; a < n; ++a) {
      const Point3& g = p.dNdx[a];
      for (int i = 0; i < 3; ++i) B(i, 3 * a + i) = g[i];
      for (int s = 0; s < 3; ++s) {  // shear s couples directions i = s, j = s + 1
        const int i = s, j = (s + 1) % 3;
        B(3 + s, 3 * a + i) = g[j];
        B(3 + s, 3 * a + j) = g[i];
      }
    }
    return;
  }
  const bool axi = k == Kinematics::Axisymmetric;
  B.resize(axi ? 4 : 3, 2 * n);
  const int shear = axi ? 3 : 2;
  for (int a = 0; a < n; ++a) {
    const Point3& g = p.dNdx[a];
    B(0, 2 * a) = g[0];
    B(1, 2 * a + 1) = g[1];
    if (axi) B(2, 2 * a) = p.N[a] / p.x[0];
    B(shear, 2 * a) = g[1];
    B(shear, 2 * a + 1) = g[0];
  }
}

// Isotropic elasticity in the strain order of strainDisplacement: lambda + 2 mu on the normal
// diagonal, lambda between normal strains, mu on the shear diagonal.
DenseMatrix elasticity(Kinematics k, const Material& m) {
  const double E = m.youngsModulus, nu = m.poissonsRatio;
  const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = m.shearModulus();
  const int normal = k == Kinematics::PlaneStrain ? 2 : 3;
  const int size = k == Kinematics::ThreeD ? 6 : (k == Kinematics::PlaneStrain ? 3 : 4);
  DenseMatrix D(size, size);
  for (int i = 0; i < size; ++i) {
    for (int j = 0; j < normal && i < normal; ++j) D(i, j) = lambda;
    D(i, i) = i < normal ? lambda + 2 * mu : mu;
  }
  return D;
}

class SolidElement : public ElementKernel {
 public:
  SolidElement(SolidShape t, Kinematics k, const Material& m)
      : topo_(t), kin_(k), mat_(m), D_(elasticity(k, m)) {
    if (k == Kinematics::ThreeD)
      comps_ = {DX, DY, DZ};
    else
      comps_ = {DX, DY};
  }
  int numNodes() const override { return nodeCount(topo_); }
  const std::vector<int>& components() const override { return comps_; }
  void stiffness(const std::vector<Point3>& x, DenseMatrix& K) const override;
  void mass(const std::vector<Point3>& x, MassKind kind, DenseMatrix& M) const override;
  // The checks of stiffness() and mass() without their products: the nodes, then det J at
  // every point of both quadrature rules.
  void checkGeometry(const std::vector<Point3>& x) const override {
    validateSolidNodes(topo_, kin_, x);
    IsoparametricPoint p;
    for (const QuadratureRule* rule : {&stiffnessRule(topo_, kin_), &massRule(topo_)})
      for (int q = 0; q < rule->size(); ++q) solidVolumeWeight(topo_, kin_, x, *rule, q, p);
  }

 private:
  DenseMatrix scalarMass(const std::vector<Point3>& x) const;

  SolidShape topo_;
  Kinematics kin_;
  Material mat_;
  DenseMatrix D_;
  std::vector<int> comps_;
};

void SolidElement::stiffness(const std::vector<Point3>& x, DenseMatrix& K) const {
  validateSolidNodes(topo_, kin_, x);
  const QuadratureRule& rule = stiffnessRule(topo_, kin_);
  const int nd = numNodes() * static_cast<int>(comps_.size()), ns = D_.rows();
  K.resize(nd, nd);
  IsoparametricPoint p;
  DenseMatrix B;
  std::vector<double> DB(size_t(ns) * nd);
  for (int q = 0; q < rule.size(); ++q) {
    const double w = solidVolumeWeight(topo_, kin_, x, rule, q, p);
    strainDisplacement(kin_, p, B);
    for (int s = 0; s < ns; ++s)
      for (int j = 0; j < nd; ++j) {
        double v = 0.0;
        for (int t = 0; t < ns; ++t) v += D_(s, t) * B(t, j);
        DB[size_t(s) * nd + j] = v;
      }
    for (int i = 0; i < nd; ++i)
      for (int s = 0; s < ns; ++s) {
        const double bw = B(s, i) * w;
        if (bw == 0.0) continue;
        for (int j = 0; j < nd; ++j) K(i, j) += bw * DB[size_t(s) * nd + j];
      }
  }
}

DenseMatrix SolidElement::scalarMass(const std::vector<Point3>& x) const {
  validateSolidNodes(topo_, kin_, x);
  const QuadratureRule& rule = massRule(topo_);
  const int n = numNodes();
  DenseMatrix m(n, n);
  IsoparametricPoint p;
  for (int q = 0; q < rule.size(); ++q) {
    const double w = mat_.density * solidVolumeWeight(topo_, kin_, x, rule, q, p);
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b) m(a, b) += w * p.N[a] * p.N[b];
  }
  return m;
}

void SolidElement::mass(const std::vector<Point3>& x, MassKind kind, DenseMatrix& M) const {
  const DenseMatrix m = scalarMass(x);
  const int n = numNodes(), nc = static_cast<int>(comps_.size());
  M.resize(n * nc, n * nc);
  if (kind == MassKind::Consistent) {
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < n; ++b)
        for (int i = 0; i < nc; ++i) M(a * nc + i, b * nc + i) = m(a, b);
    return;
  }
  const std::vector<double> l = isQuadratic(topo_) ? hrzLumping(m) : rowSumLumping(m);
  for (int a = 0; a < n; ++a)
    for (int i = 0; i < nc; ++i) M(a * nc + i, a * nc + i) = l[a];
}

}  // namespace

std::unique_ptr<ElementKernel> makeSolidElement(const std::string& topology, Kinematics kinematics,
                                                const Material& material) {
  const SolidShape t = solidTopology(topology);
  checkSolidKinematics(t, kinematics);
  checkMaterial(t, material);
  return std::make_unique<SolidElement>(t, kinematics, material);
}

double solidElementMeasure(const std::string& topology, Kinematics kinematics,
                           const std::vector<Point3>& x) {
  const SolidShape t = solidTopology(topology);
  checkSolidKinematics(t, kinematics);
  validateSolidNodes(t, kinematics, x);
  const QuadratureRule& rule = massRule(t);
  IsoparametricPoint p;
  double v = 0.0;
  for (int q = 0; q < rule.size(); ++q) v += solidVolumeWeight(t, kinematics, x, rule, q, p);
  return v;
}

}  // namespace choc
