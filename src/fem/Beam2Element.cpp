// Two-node 3D Timoshenko beam.
//
// Local DOFs per node: u v w (translations along ex ey ez), tx ty tz (rotations about them).
// Stiffness: axial EA/L, torsion GJ/L, and in each bending plane the exact two-node
// Timoshenko stiffness (cubic deflection, linear shear), with Phi = 12 E I / (kappa G A L^2);
// it is exact for end loads (cantilever tip deflection P L^3/(3EI) + P L/(kappa G A)).
//
// Consistent mass: axial rho A L/6 [2 1; 1 2], torsion rho Ip L/6 [2 1; 1 2] (Ip = Iy + Iz),
// bending: the Euler-Bernoulli consistent (Hermite cubic) translational mass, without rotary
// inertia and without the shear correction of the shape functions. This is an accepted
// approximation: it carries the exact total mass rho A L for every translation.
//
// Lumped mass: rho A L/2 on each translation of each node and rho Ip L/2 on each of the three
// rotations of each node. Using the polar inertia Ip for all three rotations (not Iy, Iz for
// the bending rotations) keeps the rotational block isotropic, so the lumped matrix stays
// diagonal after the rotation to global axes; it over-estimates the bending rotary inertia,
// which only lowers the (spurious) rotational frequencies.
#include "fem/Beam2Element.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "fem/Components.hpp"

namespace choc {

namespace {

// Part of v orthogonal to the unit vector e.
Point3 orthogonalPart(const Point3& v, const Point3& e) {
  const double p = dot(v, e);
  return {v[0] - p * e[0], v[1] - p * e[1], v[2] - p * e[2]};
}

constexpr double kParallelTol = 1e-6;  // sine of the smallest accepted angle to the axis

// K_global = T^T K_local T, T = blockdiag(R, R, R, R) with rows of R the local axes.
void toGlobal(const std::array<Point3, 3>& R, const DenseMatrix& local, DenseMatrix& global) {
  // tmp = K_local T (12x12); T(i, j) nonzero only for i/3 == j/3.
  DenseMatrix tmp(12, 12);
  for (int i = 0; i < 12; ++i)
    for (int bj = 0; bj < 4; ++bj)
      for (int c = 0; c < 3; ++c) {
        double s = 0.0;
        for (int r = 0; r < 3; ++r) s += local(i, 3 * bj + r) * R[r][c];
        tmp(i, 3 * bj + c) = s;
      }
  global.resize(12, 12);
  for (int bi = 0; bi < 4; ++bi)
    for (int c = 0; c < 3; ++c)
      for (int j = 0; j < 12; ++j) {
        double s = 0.0;
        for (int r = 0; r < 3; ++r) s += R[r][c] * tmp(3 * bi + r, j);
        global(3 * bi + c, j) = s;
      }
}

// Adds the 2x2 block a*[2 1; 1 2] on local DOFs d (node 1) and d + 6 (node 2).
void addTwoNode(DenseMatrix& M, int d, double a) {
  M(d, d) += 2 * a;
  M(d + 6, d + 6) += 2 * a;
  M(d, d + 6) += a;
  M(d + 6, d) += a;
}

// Adds the 2x2 block a*[1 -1; -1 1] on local DOFs d and d + 6.
void addBar(DenseMatrix& K, int d, double a) {
  K(d, d) += a;
  K(d + 6, d + 6) += a;
  K(d, d + 6) -= a;
  K(d + 6, d) -= a;
}

// Adds a 4x4 bending block on local DOFs {t, r, t + 6, r + 6} (t translation, r rotation).
void addBending(DenseMatrix& M, int t, int r, const double b[4][4]) {
  const int d[4] = {t, r, t + 6, r + 6};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) M(d[i], d[j]) += b[i][j];
}

// Two-node Timoshenko bending stiffness in a plane where the rotation r = +dv/dx (s = +1:
// v and tz) or r = -dw/dx (s = -1: w and ty).
void bendingStiffness(double EI, double phi, double L, double s, double b[4][4]) {
  const double c = EI / ((1.0 + phi) * L * L * L);
  const double sL = s * L, L2 = L * L;
  const double k[4][4] = {{12, 6 * sL, -12, 6 * sL},
                          {6 * sL, (4 + phi) * L2, -6 * sL, (2 - phi) * L2},
                          {-12, -6 * sL, 12, -6 * sL},
                          {6 * sL, (2 - phi) * L2, -6 * sL, (4 + phi) * L2}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) b[i][j] = c * k[i][j];
}

// Euler-Bernoulli consistent translational mass for one bending plane (sign s as above).
void bendingMass(double m, double L, double s, double b[4][4]) {
  const double c = m / 420.0;
  const double sL = s * L, L2 = L * L;
  const double k[4][4] = {{156, 22 * sL, 54, -13 * sL},
                          {22 * sL, 4 * L2, 13 * sL, -3 * L2},
                          {54, 13 * sL, 156, -22 * sL},
                          {-13 * sL, -3 * L2, -22 * sL, 4 * L2}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) b[i][j] = c * k[i][j];
}

class Beam2Element : public ElementKernel {
 public:
  Beam2Element(const Material& m, const BeamSection& s) : mat_(m), sec_(s) {
    auto require = [](bool ok, const char* what) {
      if (!ok) throw std::invalid_argument(std::string("BEAM2: ") + what);
    };
    require(m.youngsModulus > 0, "Young's modulus must be > 0");
    require(m.poissonsRatio > -1.0 && m.poissonsRatio < 0.5, "Poisson ratio must be in (-1, 0.5)");
    require(m.density >= 0, "density must be >= 0");
    require(s.area > 0, "section area must be > 0");
    require(s.Iy > 0 && s.Iz > 0, "section moments Iy, Iz must be > 0");
    require(s.torsionConstant > 0, "section torsion constant J must be > 0");
    require(s.shearCoefficientY > 0 && s.shearCoefficientZ > 0,
            "shear coefficients must be > 0");
  }
  int numNodes() const override { return 2; }
  const std::vector<int>& components() const override { return comps_; }

  void stiffness(const std::vector<Point3>& x, DenseMatrix& K) const override {
    const double L = length(x);
    const double E = mat_.youngsModulus, G = mat_.shearModulus(), A = sec_.area;
    DenseMatrix k(12, 12);
    const double ka = E * A / L, kt = G * sec_.torsionConstant / L;
    addBar(k, 0, ka);
    addBar(k, 3, kt);
    double b[4][4];
    // x-y plane: v, tz, bending about z (Iz), shear along y.
    const double phiY = 12 * E * sec_.Iz / (sec_.shearCoefficientY * G * A * L * L);
    bendingStiffness(E * sec_.Iz, phiY, L, +1.0, b);
    addBending(k, 1, 5, b);
    // x-z plane: w, ty, bending about y (Iy), shear along z.
    const double phiZ = 12 * E * sec_.Iy / (sec_.shearCoefficientZ * G * A * L * L);
    bendingStiffness(E * sec_.Iy, phiZ, L, -1.0, b);
    addBending(k, 2, 4, b);
    toGlobal(beamLocalAxes(x[0], x[1], sec_.orientation), k, K);
  }

  void mass(const std::vector<Point3>& x, MassKind kind, DenseMatrix& M) const override {
    const double L = length(x);
    const double m = mat_.density * sec_.area * L;
    const double mr = mat_.density * sec_.polarInertia() * L;
    if (kind == MassKind::Lumped) {
      // Isotropic per node, hence already global and diagonal.
      M.resize(12, 12);
      for (int n = 0; n < 2; ++n)
        for (int c = 0; c < 3; ++c) {
          M(6 * n + c, 6 * n + c) = m / 2;
          M(6 * n + 3 + c, 6 * n + 3 + c) = mr / 2;
        }
      return;
    }
    DenseMatrix k(12, 12);
    addTwoNode(k, 0, m / 6);
    addTwoNode(k, 3, mr / 6);
    double b[4][4];
    bendingMass(m, L, +1.0, b);
    addBending(k, 1, 5, b);
    bendingMass(m, L, -1.0, b);
    addBending(k, 2, 4, b);
    toGlobal(beamLocalAxes(x[0], x[1], sec_.orientation), k, M);
  }

 private:
  static double length(const std::vector<Point3>& x) {
    if (x.size() != 2) throw std::invalid_argument("BEAM2: expected 2 node coordinates");
    const Point3 d = {x[1][0] - x[0][0], x[1][1] - x[0][1], x[1][2] - x[0][2]};
    return norm(d);  // zero length is rejected by beamLocalAxes
  }
  Material mat_;
  BeamSection sec_;
  std::vector<int> comps_{DX, DY, DZ, DRX, DRY, DRZ};
};

}  // namespace

std::array<Point3, 3> beamLocalAxes(const Point3& a, const Point3& b, const Point3& orientation) {
  Point3 ex = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double L = norm(ex);
  const double scale = std::max(norm(a), norm(b));
  if (!(L > 1e-14 * scale) || L == 0.0)
    throw std::invalid_argument("BEAM2: zero-length beam (its two nodes coincide)");
  for (double& v : ex) v /= L;
  Point3 ey;
  if (norm(orientation) == 0.0) {
    ey = orthogonalPart({0.0, 1.0, 0.0}, ex);
    if (norm(ey) < kParallelTol) ey = orthogonalPart({0.0, 0.0, 1.0}, ex);
  } else {
    ey = orthogonalPart(orientation, ex);
    if (norm(ey) < kParallelTol * norm(orientation))
      throw std::invalid_argument(
          "BEAM2: the section orientation vector (local y axis) is parallel to the beam axis; "
          "give a direction not along the beam");
  }
  const double ny = norm(ey);
  for (double& v : ey) v /= ny;
  return {ex, ey, cross(ex, ey)};
}

std::unique_ptr<ElementKernel> makeBeam2(const Material& material, const BeamSection& section) {
  return std::make_unique<Beam2Element>(material, section);
}

}  // namespace choc
