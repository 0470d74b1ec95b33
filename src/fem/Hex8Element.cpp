// Eight-node trilinear hexahedron. Stiffness and consistent mass by 2x2x2 Gauss quadrature
// (the mass is integrated exactly for a parallelepiped); lumped mass = row sums of the
// consistent mass, which are positive for HEX8.
#include "fem/Hex8Element.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "fem/Components.hpp"

namespace choc {

namespace {

// Natural coordinates of the nodes, Exodus order: bottom face (zeta = -1) counter-clockwise
// seen from +zeta, then the top face.
constexpr double kNode[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};

void shape(const Point3& xi, double N[8], double dN[8][3]) {
  for (int a = 0; a < 8; ++a) {
    const double f[3] = {1 + kNode[a][0] * xi[0], 1 + kNode[a][1] * xi[1],
                         1 + kNode[a][2] * xi[2]};
    N[a] = f[0] * f[1] * f[2] / 8;
    dN[a][0] = kNode[a][0] * f[1] * f[2] / 8;
    dN[a][1] = f[0] * kNode[a][1] * f[2] / 8;
    dN[a][2] = f[0] * f[1] * kNode[a][2] / 8;
  }
}

// J(i, j) = dx_j / dxi_i; returns det J and fills dN/dx when det J > 0.
double jacobian(const std::vector<Point3>& x, const Point3& xi, double N[8],
                Hex8Gradients* dNdx) {
  if (x.size() != 8) throw std::invalid_argument("HEX8: expected 8 node coordinates");
  double dN[8][3];
  shape(xi, N, dN);
  double J[3][3] = {};
  for (int a = 0; a < 8; ++a)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) J[i][j] += dN[a][i] * x[a][j];
  const double det = J[0][0] * (J[1][1] * J[2][2] - J[1][2] * J[2][1]) -
                     J[0][1] * (J[1][0] * J[2][2] - J[1][2] * J[2][0]) +
                     J[0][2] * (J[1][0] * J[2][1] - J[1][1] * J[2][0]);
  if (!(det > 0.0)) {
    std::ostringstream msg;
    msg << "inverted or degenerate HEX8: Jacobian determinant " << det
        << " <= 0 at natural point (" << xi[0] << ", " << xi[1] << ", " << xi[2]
        << "); check the node order (Exodus: bottom face counter-clockwise, then top face)";
    throw std::invalid_argument(msg.str());
  }
  if (dNdx) {
    // inv(J) by cofactors; dN/dx_j = sum_i inv(J)(j, i) dN/dxi_i.
    double Ji[3][3];
    Ji[0][0] = (J[1][1] * J[2][2] - J[1][2] * J[2][1]) / det;
    Ji[0][1] = (J[0][2] * J[2][1] - J[0][1] * J[2][2]) / det;
    Ji[0][2] = (J[0][1] * J[1][2] - J[0][2] * J[1][1]) / det;
    Ji[1][0] = (J[1][2] * J[2][0] - J[1][0] * J[2][2]) / det;
    Ji[1][1] = (J[0][0] * J[2][2] - J[0][2] * J[2][0]) / det;
    Ji[1][2] = (J[0][2] * J[1][0] - J[0][0] * J[1][2]) / det;
    Ji[2][0] = (J[1][0] * J[2][1] - J[1][1] * J[2][0]) / det;
    Ji[2][1] = (J[0][1] * J[2][0] - J[0][0] * J[2][1]) / det;
    Ji[2][2] = (J[0][0] * J[1][1] - J[0][1] * J[1][0]) / det;
    for (int a = 0; a < 8; ++a)
      for (int j = 0; j < 3; ++j)
        (*dNdx)[a][j] = Ji[j][0] * dN[a][0] + Ji[j][1] * dN[a][1] + Ji[j][2] * dN[a][2];
  }
  return det;
}

class Hex8Element : public ElementKernel {
 public:
  explicit Hex8Element(const Material& m) : mat_(m) {
    if (!(m.youngsModulus > 0)) throw std::invalid_argument("HEX8: Young's modulus must be > 0");
    if (!(m.poissonsRatio > -1.0 && m.poissonsRatio < 0.5))
      throw std::invalid_argument("HEX8: Poisson ratio must be in (-1, 0.5)");
    if (!(m.density >= 0)) throw std::invalid_argument("HEX8: density must be >= 0");
  }
  int numNodes() const override { return 8; }
  const std::vector<int>& components() const override { return comps_; }

  void checkGeometry(const std::vector<Point3>& x) const override {
    double N[8];
    for (const Point3& xi : hex8GaussPoints()) jacobian(x, xi, N, nullptr);
  }

  void stiffness(const std::vector<Point3>& x, DenseMatrix& K) const override {
    const double E = mat_.youngsModulus, nu = mat_.poissonsRatio;
    const double lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const double mu = mat_.shearModulus();
    K.resize(24, 24);
    double N[8];
    Hex8Gradients g;
    for (const Point3& gp : hex8GaussPoints()) {
      const double w = jacobian(x, gp, N, &g);  // Gauss weight 1
      // K_ab(i, j) = [lambda g_a,i g_b,j + mu (g_a,j g_b,i + delta_ij g_a . g_b)] dV
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) {
          const double gg = g[a][0] * g[b][0] + g[a][1] * g[b][1] + g[a][2] * g[b][2];
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
              double k = lambda * g[a][i] * g[b][j] + mu * g[a][j] * g[b][i];
              if (i == j) k += mu * gg;
              K(3 * a + i, 3 * b + j) += w * k;
            }
        }
    }
  }

  void mass(const std::vector<Point3>& x, MassKind kind, DenseMatrix& M) const override {
    double m[8][8] = {};
    double N[8];
    for (const Point3& gp : hex8GaussPoints()) {
      const double w = mat_.density * jacobian(x, gp, N, nullptr);
      for (int a = 0; a < 8; ++a)
        for (int b = 0; b < 8; ++b) m[a][b] += w * N[a] * N[b];
    }
    M.resize(24, 24);
    for (int a = 0; a < 8; ++a) {
      double rowSum = 0.0;
      for (int b = 0; b < 8; ++b) rowSum += m[a][b];
      for (int i = 0; i < 3; ++i) {
        if (kind == MassKind::Lumped) {
          M(3 * a + i, 3 * a + i) = rowSum;
        } else {
          for (int b = 0; b < 8; ++b) M(3 * a + i, 3 * b + i) = m[a][b];
        }
      }
    }
  }

 private:
  Material mat_;
  std::vector<int> comps_{DX, DY, DZ};
};

}  // namespace

double hex8Gradients(const std::vector<Point3>& x, const Point3& xi, Hex8Gradients& dNdx) {
  double N[8];
  return jacobian(x, xi, N, &dNdx);
}

const std::array<Point3, 8>& hex8GaussPoints() {
  static const std::array<Point3, 8> points = [] {
    const double g = 1.0 / std::sqrt(3.0);
    std::array<Point3, 8> p;
    for (int a = 0; a < 8; ++a) p[a] = {kNode[a][0] * g, kNode[a][1] * g, kNode[a][2] * g};
    return p;
  }();
  return points;
}

std::unique_ptr<ElementKernel> makeHex8(const Material& material) {
  return std::make_unique<Hex8Element>(material);
}

}  // namespace choc
