// Pressures on the current faces, with their load stiffness (header).
#include "physics/FollowerPressure.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/DofMap.hpp"
#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"
#include "physics/Loads.hpp"

namespace choc {
namespace {

// Shape functions of a face or edge and their derivatives along xi and eta.
void faceShape(const Face& f, double xi, double eta, std::vector<double>& N, std::vector<std::array<double, 2>>& dN) {
  if (f.edgeNodes == 2) {
    N = {0.5 * (1 - xi), 0.5 * (1 + xi)};
    dN = {{{-0.5, 0.0}}, {{0.5, 0.0}}};
    return;
  }
  if (f.edgeNodes == 3) {
    N = {0.5 * xi * (xi - 1), 0.5 * xi * (xi + 1), 1 - xi * xi};
    dN = {{{xi - 0.5, 0.0}}, {{xi + 0.5, 0.0}}, {{-2 * xi, 0.0}}};
    return;
  }
  std::vector<Point3> d;
  shapeFunctions(f.shape, Point3{xi, eta, 0.0}, N, d);
  dN.resize(d.size());
  for (size_t a = 0; a < d.size(); ++a) dN[a] = {d[a][0], d[a][1]};
}

// [a]x b = a x b: the cross-product matrix's entry (i, j).
double crossMatrix(const Point3& a, int i, int j) {
  static const int eps[3][3][3] = {{{0, 0, 0}, {0, 0, 1}, {0, -1, 0}},
                                   {{0, 0, -1}, {0, 0, 0}, {1, 0, 0}},
                                   {{0, 1, 0}, {-1, 0, 0}, {0, 0, 0}}};
  double s = 0.0;
  for (int k = 0; k < 3; ++k) s += eps[i][k][j] * a[k];
  return s;
}

const QuadratureRule& faceRule(const Face& f) { return f.edgeNodes ? gaussBoxRule(1, 3) : massRule(f.shape); }

}  // namespace

void followerFaceForce(const Face& face, const PressureField& p, const std::vector<Point3>& x, bool axisymmetric,
                       std::vector<double>& force, DenseMatrix* K) {
  const int n = static_cast<int>(face.nodes.size());
  force.assign(size_t(3 * n), 0.0);
  if (K) K->resize(3 * n, 3 * n);
  const QuadratureRule& rule = faceRule(face);
  std::vector<double> N;
  std::vector<std::array<double, 2>> dN;
  for (int q = 0; q < rule.size(); ++q) {
    faceShape(face, rule.points[q][0], rule.points[q][1], N, dN);
    Point3 X{}, xq{}, t1{}, t2{};
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d) {
        X[d] += N[a] * face.x[a][d];
        xq[d] += N[a] * x[a][d];
        t1[d] += dN[a][0] * x[a][d];
        t2[d] += dN[a][1] * x[a][d];
      }
    if (face.edgeNodes) t2 = {0.0, 0.0, 1.0};
    const double ring = axisymmetric && face.edgeNodes ? 2.0 * M_PI * xq[0] : 1.0;
    const Point3 nA = cross(t1, t2);  // outward normal times the area element (current)
    const double w = -p.at(X) * rule.weights[q];
    for (int a = 0; a < n; ++a)
      for (int i = 0; i < 3; ++i) force[size_t(3 * a + i)] += w * ring * N[a] * nA[i];
    if (!K) continue;
    // d nA / d x_b = dN_b/dxi [e_j x t2] + dN_b/deta [t1 x e_j] = -dN_b/dxi [t2]x + dN_b/deta [t1]x
    for (int b = 0; b < n; ++b)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          double dn = -dN[b][0] * crossMatrix(t2, i, j);
          if (!face.edgeNodes) dn += dN[b][1] * crossMatrix(t1, i, j);
          double d = ring * dn;
          if (axisymmetric && face.edgeNodes && j == 0) d += 2.0 * M_PI * N[b] * nA[i];
          for (int a = 0; a < n; ++a) (*K)(3 * a + i, 3 * b + j) += w * N[a] * d;
        }
  }
}

FollowerPressure::FollowerPressure(std::string name, std::vector<Face> faces, PressureField p, double rampTime,
                                   bool axisymmetric, const DofMap& dofs, int components, const CrsMatrix& K)
    : name_(std::move(name)), p_(p), rampTime_(rampTime), axisymmetric_(axisymmetric), colMap_(K.getColMap()),
      importer_(K.getGraph()->getImporter()) {
  if (!importer_.is_null()) uCol_ = rcp(new Vector(colMap_));
  const Map& rows = *K.getRowMap();
  const Map& cols = *K.getColMap();
  const LO invalid = Teuchos::OrdinalTraits<LO>::invalid();
  for (Face& f : faces) {
    Loaded l{std::move(f), {}, {}};
    bool mine = false;
    for (int node : l.face.nodes)
      for (int c = 0; c < 3; ++c) {
        const long long d = c < components ? dofs.dof(node, c) : -1;
        LO col = d < 0 ? LO(-1) : cols.getLocalElement(GO(d));
        LO row = d < 0 ? LO(-1) : rows.getLocalElement(GO(d));
        if (col == invalid) col = -1;
        if (row == invalid) row = -1;
        l.col.push_back(col);
        l.row.push_back(row);
        mine = mine || row >= 0;
      }
    if (mine) faces_.push_back(std::move(l));  // a face with a row here: all its DOFs are columns
  }
}

double FollowerPressure::factor(double t) const { return rampFactor(rampTime_, t); }

template <class Visit>
void FollowerPressure::forEachFace(const Teuchos::ArrayRCP<const double>& uCol, bool withTangent, Visit&& visit) const {
  std::vector<Point3> x;
  std::vector<double> f;
  DenseMatrix Kf;
  for (const Loaded& l : faces_) {
    x = l.face.x;
    for (size_t a = 0; a < x.size(); ++a)
      for (int c = 0; c < 3; ++c)
        if (l.col[3 * a + size_t(c)] >= 0) x[a][size_t(c)] += uCol[l.col[3 * a + size_t(c)]];
    followerFaceForce(l.face, p_, x, axisymmetric_, f, withTangent ? &Kf : nullptr);
    visit(l, f, Kf);
  }
}

void FollowerPressure::subtractForce(const Teuchos::ArrayRCP<const double>& uCol, double t,
                                     Teuchos::ArrayRCP<double>& out) const {
  const double lambda = factor(t);
  if (lambda == 0.0) return;
  forEachFace(uCol, false, [&](const Loaded& l, const std::vector<double>& f, const DenseMatrix&) {
    for (size_t k = 0; k < l.row.size(); ++k)
      if (l.row[k] >= 0) out[l.row[k]] -= lambda * f[k];
  });
}

void FollowerPressure::addTangent(const Teuchos::ArrayRCP<const double>& uCol, double t, CrsMatrix& K) const {
  const double lambda = factor(t);
  if (lambda == 0.0) return;
  std::vector<LO> cols;
  std::vector<double> vals;
  forEachFace(uCol, true, [&](const Loaded& l, const std::vector<double>&, const DenseMatrix& Kf) {
    for (size_t i = 0; i < l.row.size(); ++i) {
      if (l.row[i] < 0) continue;
      cols.clear();
      vals.clear();
      for (size_t j = 0; j < l.col.size(); ++j)
        if (l.col[j] >= 0) cols.push_back(l.col[j]), vals.push_back(-lambda * Kf(int(i), int(j)));
      const LO found = K.sumIntoLocalValues(l.row[i], Teuchos::ArrayView<const LO>(cols), Teuchos::ArrayView<const double>(vals));
      if (size_t(found) != cols.size())  // the faces are on finite-strain blocks, whose pattern is full
        throw std::logic_error("follower pressure '" + name_ + "': load stiffness entries outside the stiffness' graph");
    }
  });
}

void FollowerPressure::addForce(const Vector& u, double t, Vector& out) const {
  const double lambda = factor(t);
  if (lambda == 0.0) return;
  const Vector* onCols = &u;
  if (!importer_.is_null()) {
    uCol_->doImport(u, *importer_, Tpetra::INSERT);
    onCols = uCol_.get();
  }
  auto o = out.getDataNonConst();
  forEachFace(onCols->getData(), false, [&](const Loaded& l, const std::vector<double>& f, const DenseMatrix&) {
    for (size_t k = 0; k < l.row.size(); ++k)
      if (l.row[k] >= 0) o[l.row[k]] += lambda * f[k];
  });
}

}  // namespace choc
