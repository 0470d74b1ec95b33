// Mass redistribution (Khenous, Laborde, Renard 2008): the nodes of the contact surfaces carry
// no mass; the mass of each element touching them moves onto its other nodes through a
// partition of unity (M' = T^T M T with T 1 = 1), so that for every translation direction c
//   1_c^T M' 1_c = 1_c^T M 1_c = rho V                                         (element mass)
// exactly in exact arithmetic. In floating point both sides are sums of the n^2 entries of
// an n x n matrix (n = 24): they agree to n^2 u times the sum of the absolute entries
// (Higham, eq. 4.4, gamma_{n^2}), which is the tolerance below.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/Assembler.hpp"
#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "test_fem_helpers.hpp"

using namespace choc;
using namespace choc::test;

namespace {

const Material kSteel{2e11, 0.3, 7800.0};
const double kU = std::numeric_limits<double>::epsilon() / 2;

// A brick [0,a]x[0,b]x[0,h]; nodes 0..3 on z = 0 (the contact face), 4..7 on z = h.
std::vector<Point3> brick(double a, double b, double h) {
  return {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0}, {0, 0, h}, {a, 0, h}, {a, b, h}, {0, b, h}};
}

// 1_c^T M 1_c and x_d-weighted first moment sum_ij x_d(i) M(ic, jc), and the sum of |M|.
double translationMass(const DenseMatrix& M, int c, double& absSum) {
  double s = 0.0;
  absSum = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      s += M(i * 3 + c, j * 3 + c);
      absSum += std::fabs(M(i * 3 + c, j * 3 + c));
    }
  return s;
}

double firstMoment(const DenseMatrix& M, const std::vector<Point3>& x, int c, int d) {
  double s = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) s += x[i][d] * M(i * 3 + c, j * 3 + c);
  return s;
}

void checkElement(MassKind kind) {
  const double a = 0.02, b = 0.03, h = 0.025, rho = kSteel.density;
  const auto x = brick(a, b, h);
  auto hex = makeHex8(kSteel);
  DenseMatrix M0, M1;
  hex->mass(x, kind, M0);
  M1 = M0;
  const std::vector<char> massless = {1, 1, 1, 1, 0, 0, 0, 0};
  redistributeElementMass(x, massless, 3, kind, M1);
  const double m = rho * a * b * h;
  const double n2u = 24.0 * 24.0 * kU / (1 - 24.0 * 24.0 * kU);
  for (int c = 0; c < 3; ++c) {
    double abs0 = 0, abs1 = 0;
    const double m0 = translationMass(M0, c, abs0), m1 = translationMass(M1, c, abs1);
    EXPECT_NEAR(m1, m0, n2u * (abs0 + abs1)) << "component " << c << ": element mass kept";
    EXPECT_NEAR(m1, m, n2u * (abs1 + m)) << "component " << c;
    // Centre of mass in the contact plane (x, y): the massless node follows the node across
    // the element along the normal, at the same (x, y).
    for (int d = 0; d < 2; ++d)
      EXPECT_NEAR(firstMoment(M1, x, c, d), firstMoment(M0, x, c, d), n2u * (abs0 + abs1) * std::max(a, b));
    // Across the contact plane the centre moves to the far face: z_G = h (was h/2).
    EXPECT_NEAR(firstMoment(M1, x, c, 2) / m1, h, 1e-12 * h);
  }
  // The contact nodes' rows and columns are exactly zero.
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c)
      for (int j = 0; j < 24; ++j) {
        EXPECT_EQ(M1(k * 3 + c, j), 0.0);
        EXPECT_EQ(M1(j, k * 3 + c), 0.0);
      }
  EXPECT_EQ(asymmetry(M1), 0.0);
  // Positive semi-definite (a congruence of a positive matrix): eigenvalues >= -n u ||M||.
  const auto ev = symmetricEigenvalues(M1);
  EXPECT_GE(ev.front(), -24 * kU * maxAbs(M1) * 24);
  if (kind == MassKind::Lumped) {
    for (int i = 0; i < 24; ++i)
      for (int j = 0; j < 24; ++j)
        if (i != j) EXPECT_EQ(M1(i, j), 0.0) << "a lumped matrix stays diagonal";
  }
}

}  // namespace

TEST(MassRedistribution, ConsistentHex8KeepsElementMassAndInPlaneCentre) { checkElement(MassKind::Consistent); }

TEST(MassRedistribution, LumpedHex8KeepsElementMassAndStaysDiagonal) { checkElement(MassKind::Lumped); }

TEST(MassRedistribution, NoMasslessNodeLeavesTheMatrixUnchanged) {
  const auto x = brick(0.02, 0.02, 0.02);
  auto hex = makeHex8(kSteel);
  DenseMatrix M0, M1;
  hex->mass(x, MassKind::Consistent, M0);
  M1 = M0;
  redistributeElementMass(x, std::vector<char>(8, 0), 3, MassKind::Consistent, M1);
  for (int i = 0; i < 24; ++i)
    for (int j = 0; j < 24; ++j) EXPECT_EQ(M1(i, j), M0(i, j));
}

TEST(MassRedistribution, AnElementWithEveryNodeMasslessIsRefused) {
  const auto x = brick(0.02, 0.02, 0.02);
  auto hex = makeHex8(kSteel);
  DenseMatrix M;
  hex->mass(x, MassKind::Consistent, M);
  EXPECT_THROW(redistributeElementMass(x, std::vector<char>(8, 1), 3, MassKind::Consistent, M),
               std::invalid_argument);
}

// The benchmark scene (axial DZ only, bar 2 clamped at its far face) with the nodes of both
// contact faces massless: the assembled total mass 1^T M 1 is the same (to the rounding of
// summing the entries), and the contact nodes' rows are zero.
TEST(MassRedistribution, AssembledBenchmarkMassIsKept) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  const Mesh mesh = generateBarImpactMesh(o);
  std::vector<BlockPhysics> physics(mesh.blocks.size());
  for (auto& p : physics) p.kernel = makeHex8(kSteel);
  auto mask = Assembler::carriedComponents(mesh, physics);
  for (auto& bits : mask) bits &= std::uint8_t(1u << DZ);
  for (int n : mesh.findNodeSet("CL_POU2")->nodes) mask[n] = 0;
  auto comm = Teuchos::DefaultComm<int>::getComm();
  DofMap dofs(mask, comm->getSize(), comm->getRank());
  Assembler asmb(mesh, dofs, physics, comm);
  std::vector<char> massless(mesh.numNodes(), 0);
  int nMassless = 0;
  for (const char* ss : {"CNT_POU1", "CNT_POU2"}) {
    const SideSet* s = mesh.findSideSet(ss);
    ASSERT_NE(s, nullptr);
    for (size_t k = 0; k < s->elements.size(); ++k)
      for (int n : mesh.sideNodes(s->elements[k], s->sides[k])) nMassless += !massless[n], massless[n] = 1;
  }
  ASSERT_EQ(nMassless, 8);
  auto M0 = asmb.mass(), M1 = asmb.mass(massless);
  Vector one(M0->getRowMap()), y0(M0->getRowMap()), y1(M0->getRowMap());
  one.putScalar(1.0);
  M0->apply(one, y0);
  M1->apply(one, y1);
  const double m0 = one.dot(y0), m1 = one.dot(y1);
  // Free DZ mass: both bars minus what the clamped face takes. Along the axis the consistent
  // HEX8 mass of an element is the bar's rho S h / 6 [2 1; 1 2] between its two faces, so
  // the clamped element's free-free block sums to rho S h / 3: 2/3 of its mass is lost.
  const double rho = kSteel.density, S = 4e-4, h = 0.02;
  EXPECT_NEAR(m0, rho * S * 2.0 - 2.0 / 3.0 * rho * S * h, 1e-12 * m0);
  const double nnz = double(M1->getGlobalNumEntries());
  EXPECT_NEAR(m1, m0, 2 * nnz * kU * m0) << "mass kept by the redistribution";
  for (int n = 0; n < mesh.numNodes(); ++n) {
    if (!massless[n] || !dofs.ownsNode(n)) continue;
    const GO g = GO(dofs.dof(n, DZ));
    const size_t ne = M1->getNumEntriesInGlobalRow(g);
    CrsMatrix::nonconst_global_inds_host_view_type cols("cols", ne);
    CrsMatrix::nonconst_values_host_view_type vals("vals", ne);
    size_t got = 0;
    M1->getGlobalRowCopy(g, cols, vals, got);
    for (size_t k = 0; k < got; ++k) EXPECT_EQ(vals[k], 0.0) << "node " << n;
  }
  std::vector<char> wrongSize(3, 0);
  EXPECT_THROW(asmb.mass(wrongSize), std::invalid_argument);
}
