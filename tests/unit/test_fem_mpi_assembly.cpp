// Rank independence of the assembly (run by ctest on 1 and on 2 ranks).
//
// The Assembler computes, on each rank, every element touching one of its nodes and sums each
// row in global element order, so K and M must be bitwise identical whatever the number of
// ranks. Each test assembles the same model twice: on the default communicator (distributed)
// and on MPI_COMM_SELF (the whole model on every rank: the serial reference). Every rank then
// compares the rows it owns in the distributed matrix with the same rows of its serial copy,
// entry by entry and bit for bit; since every row is owned by exactly one rank, all entries
// are compared, and the number of mismatches is summed over the ranks.
//
// Matrix-vector products are also compared. A distributed product sums a row in the order of
// the local column map (owned columns first), which may differ from the serial order, so the
// two results agree to rounding only: for a row with n stored entries, any two summation
// orders of sum_j a_ij x_j differ by at most 2 gamma_n sum_j |a_ij x_j|, gamma_n = n u/(1-n u),
// u = 2^-53 (Higham, Accuracy and Stability of Numerical Algorithms, eq. 4.4).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <map>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>

#include "fem/Assembler.hpp"
#include "fem/Beam2Element.hpp"
#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "mesh/BarImpactMesh.hpp"

namespace choc {
namespace {

using Row = std::map<GO, double>;

Row globalRow(const CrsMatrix& A, GO row) {
  const size_t n = A.getNumEntriesInGlobalRow(row);
  CrsMatrix::nonconst_global_inds_host_view_type cols("cols", n);
  CrsMatrix::nonconst_values_host_view_type vals("vals", n);
  size_t got = 0;
  A.getGlobalRowCopy(row, cols, vals, got);
  Row r;
  for (size_t k = 0; k < got; ++k) {
    EXPECT_EQ(r.count(cols[k]), 0u) << "duplicate column " << cols[k] << " in row " << row;
    r[cols[k]] = vals[k];
  }
  return r;
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

long long sumOverRanks(long long v) {
  long long s = 0;
  MPI_Allreduce(&v, &s, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return s;
}

// A deterministic vector that depends on the global index only.
double probe(GO g) { return std::sin(0.37 * double(g) + 0.1) + 0.01 * double(g % 7); }

// Compares the distributed matrix D with the serial matrix S (same model): row by row, bit for
// bit, then y = D x against S x. Returns nothing; records failures.
void compareWithSerial(const CrsMatrix& D, const CrsMatrix& S, const std::string& what) {
  ASSERT_EQ(D.getGlobalNumRows(), S.getGlobalNumRows()) << what;
  ASSERT_EQ(D.getGlobalNumEntries(), S.getGlobalNumEntries()) << what;
  const auto rowMap = D.getRowMap();
  long long mismatches = 0, compared = 0;
  for (size_t i = 0; i < D.getNodeNumRows(); ++i) {
    const GO g = rowMap->getGlobalElement(LO(i));
    const Row d = globalRow(D, g), s = globalRow(S, g);
    if (d.size() != s.size()) {
      ++mismatches;
      ADD_FAILURE() << what << ": row " << g << " has " << d.size() << " entries, serial "
                    << s.size();
      continue;
    }
    for (const auto& [c, v] : d) {
      ++compared;
      auto it = s.find(c);
      if (it == s.end() || !sameBits(v, it->second)) {
        if (++mismatches <= 5)
          ADD_FAILURE() << what << ": entry (" << g << ", " << c << ") = " << v << ", serial "
                        << (it == s.end() ? std::string("absent") : std::to_string(it->second));
      }
    }
  }
  EXPECT_EQ(sumOverRanks(mismatches), 0) << what << ": entries differing from the serial assembly";
  EXPECT_EQ(sumOverRanks(compared), static_cast<long long>(S.getGlobalNumEntries()))
      << what << ": every entry is compared exactly once";

  // Matrix-vector products.
  MultiVector xd(D.getDomainMap(), 1), yd(D.getRangeMap(), 1);
  MultiVector xs(S.getDomainMap(), 1), ys(S.getRangeMap(), 1);
  for (size_t i = 0; i < xd.getLocalLength(); ++i)
    xd.replaceLocalValue(LO(i), 0, probe(D.getDomainMap()->getGlobalElement(LO(i))));
  for (size_t i = 0; i < xs.getLocalLength(); ++i)
    xs.replaceLocalValue(LO(i), 0, probe(S.getDomainMap()->getGlobalElement(LO(i))));
  D.apply(xd, yd);
  S.apply(xs, ys);
  auto yD = yd.getData(0), yS = ys.getData(0);
  const double u = std::numeric_limits<double>::epsilon() / 2;
  long long bad = 0;
  for (size_t i = 0; i < yd.getLocalLength(); ++i) {
    const GO g = D.getRangeMap()->getGlobalElement(LO(i));
    const Row s = globalRow(S, g);
    double absSum = 0.0;
    for (const auto& [c, v] : s) absSum += std::fabs(v * probe(c));
    const double n = double(s.size());
    const double bound = 2.0 * (n * u / (1.0 - n * u)) * absSum;
    const double ref = yS[S.getRangeMap()->getLocalElement(g)];
    if (!(std::fabs(yD[i] - ref) <= bound)) {
      if (++bad <= 5)
        ADD_FAILURE() << what << ": (A x)[" << g << "] = " << yD[i] << ", serial " << ref
                      << ", difference " << std::fabs(yD[i] - ref) << " > bound " << bound;
    }
  }
  EXPECT_EQ(sumOverRanks(bad), 0) << what << ": matrix-vector products differing from serial";
}

struct Scene {
  Mesh mesh;
  std::vector<BlockPhysics> physics;
  std::vector<std::uint8_t> mask;
};

// Assembles K and M on `comm` (with the DofMap of that communicator) and returns them; M with
// the nodes flagged in `massless` massless when it is not empty (redistributed mass).
std::pair<RCP<CrsMatrix>, RCP<CrsMatrix>> assemble(const Scene& m, RCP<const Comm> comm,
                                                   const std::vector<char>& massless = {},
                                                   const std::vector<NodalSpring>& springs = {}) {
  DofMap dofs(m.mask, comm->getSize(), comm->getRank());
  Assembler a(m.mesh, dofs, m.physics, comm);
  return {a.stiffness(springs), massless.empty() ? a.mass() : a.mass(massless)};
}

void checkRankIndependence(const Scene& m, const std::string& what,
                           const std::vector<char>& massless = {}) {
  auto world = Teuchos::DefaultComm<int>::getComm();
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  auto [Kd, Md] = assemble(m, world, massless);
  auto [Ks, Ms] = assemble(m, self, massless);
  ASSERT_EQ(Ks->getComm()->getSize(), 1);
  // On 2 ranks, each rank must really own part of the rows (else the test proves nothing).
  if (world->getSize() > 1) {
    EXPECT_LT(Kd->getNodeNumRows(), Ks->getNodeNumRows()) << what << ": rows are not distributed";
  }
  compareWithSerial(*Kd, *Ks, what + " K");
  compareWithSerial(*Md, *Ms, what + " M");
}

// The 3D benchmark scene (bars along z, 2 x 50 HEX8, 1 x 1 across), steel, consistent mass;
// the mask is left to each test.
Scene hex8BenchmarkScene() {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  Scene m;
  m.mesh = generateBarImpactMesh(o);
  Material steel{2e11, 0.3, 7800.0};
  m.physics.resize(m.mesh.blocks.size());
  for (auto& p : m.physics) p.kernel = makeHex8(steel);
  return m;
}

// The 3D benchmark scene: 2 x 50 HEX8 along, 1 x 1 across, every translation free except the
// clamped face of bar 2 (the lateral DOFs are left free to exercise every coupling).
TEST(MpiAssembly, Hex8BenchmarkMeshIsRankIndependent) {
  Scene m = hex8BenchmarkScene();
  m.mask = Assembler::carriedComponents(m.mesh, m.physics);
  for (int n : m.mesh.findNodeSet("CL_POU2")->nodes) m.mask[n] &= std::uint8_t(~(1u << DZ));
  ASSERT_EQ(m.mesh.numNodes(), 408);
  checkRankIndependence(m, "HEX8 3D");
}

// Lumped mass on one bar, consistent on the other; the benchmark's 3D constraints (DX = DY = 0
// everywhere, DZ = 0 on the clamped face).
TEST(MpiAssembly, Hex8BenchmarkConstraintsAndLumpedMassAreRankIndependent) {
  Scene m = hex8BenchmarkScene();
  m.physics[0].mass = MassKind::Lumped;
  m.mask = Assembler::carriedComponents(m.mesh, m.physics);
  for (auto& b : m.mask) b &= std::uint8_t(1u << DZ);
  for (int n : m.mesh.findNodeSet("CL_POU2")->nodes) m.mask[n] = 0;
  checkRankIndependence(m, "HEX8 3D axial");
}

// Redistributed mass (the contact faces' nodes massless, SDNL111 C/D/E 'Contact Mass' =
// 'redistributed'): the element-by-element redistribution keeps the bitwise rank independence.
TEST(MpiAssembly, Hex8RedistributedContactMassIsRankIndependent) {
  Scene m = hex8BenchmarkScene();
  m.mask = Assembler::carriedComponents(m.mesh, m.physics);
  for (int n : m.mesh.findNodeSet("CL_POU2")->nodes) m.mask[n] &= std::uint8_t(~(1u << DZ));
  std::vector<char> massless(m.mesh.numNodes(), 0);
  for (const char* name : {"CNT_POU1", "CNT_POU2"}) {
    const SideSet* ss = m.mesh.findSideSet(name);
    ASSERT_NE(ss, nullptr);
    for (size_t k = 0; k < ss->elements.size(); ++k)
      for (int n : m.mesh.sideNodes(ss->elements[k], ss->sides[k])) massless[n] = 1;
  }
  checkRankIndependence(m, "HEX8 3D redistributed", massless);
}

// The 1D scene: 2 x 50 BEAM2, 6 DOF per node, D clamped.
TEST(MpiAssembly, Beam2BenchmarkMeshIsRankIndependent) {
  BarImpactOptions o;
  o.dimension = 1;
  Scene m;
  m.mesh = generateBarImpactMesh(o);
  Material steel{2e11, 0.0, 7800.0};
  m.physics.resize(m.mesh.blocks.size());
  for (auto& p : m.physics) p.kernel = makeBeam2(steel, squareSection(0.02));
  m.mask = Assembler::carriedComponents(m.mesh, m.physics);
  for (int n : m.mesh.findNodeSet("D")->nodes) m.mask[n] = 0;
  ASSERT_EQ(m.mesh.numNodes(), 102);
  checkRankIndependence(m, "BEAM2 1D");
}

// Springs to ground (Model/Springs): K gains k d d^T on each spring node's free translations
// (a fixed component drops out), nothing else, and stays bitwise rank-independent.
TEST(MpiAssembly, GroundedSpringsAddTheirBlockOnlyAndAreRankIndependent) {
  Scene m = hex8BenchmarkScene();
  m.mask = Assembler::carriedComponents(m.mesh, m.physics);
  const std::vector<int>& clamped = m.mesh.findNodeSet("CL_POU2")->nodes;
  for (int n : clamped) m.mask[n] &= std::uint8_t(~(1u << DZ));
  const Point3 d{1.0 / 3.0, 2.0 / 3.0, 2.0 / 3.0};
  const double k = 3e8;
  std::vector<NodalSpring> springs;
  for (int n : {0, 7, 100}) springs.push_back({n, d, k});
  springs.push_back({clamped[0], d, k});  // its DZ is fixed
  auto world = Teuchos::DefaultComm<int>::getComm();
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  auto [Kd, Md] = assemble(m, world, {}, springs);
  auto [Ks, Ms] = assemble(m, self, {}, springs);
  compareWithSerial(*Kd, *Ks, "HEX8 with springs K");
  auto [K0, M0] = assemble(m, self);
  DofMap dofs(m.mask, 1, 0);
  std::map<std::pair<long long, long long>, double> expected;
  for (const NodalSpring& s : springs)
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (dofs.dof(s.node, i) >= 0 && dofs.dof(s.node, j) >= 0)
          expected[{dofs.dof(s.node, i), dofs.dof(s.node, j)}] += k * d[i] * d[j];
  ASSERT_EQ(expected.size(), 3u * 9u + 4u);  // the clamped node keeps its DX, DY block
  for (size_t i = 0; i < K0->getNodeNumRows(); ++i) {
    const GO g = K0->getRowMap()->getGlobalElement(LO(i));
    const Row with = globalRow(*Ks, g), without = globalRow(*K0, g);
    ASSERT_EQ(with.size(), without.size()) << "row " << g;
    for (const auto& [c, v] : with) {
      const auto e = expected.find({g, c});
      const double added = e == expected.end() ? 0.0 : e->second;
      EXPECT_NEAR(v - without.at(c), added, 1e-12 * std::abs(v)) << "row " << g << ", column " << c;
    }
  }
}

// The element eigenvalue bound of the critical step (a maximum over elements plus the springs'
// Gershgorin rows) is the same number on any number of ranks: each element is computed whole
// on every rank that holds one of its nodes, and the maximum does not depend on the order.
TEST(MpiAssembly, ElementEigenvalueBoundIsRankIndependent) {
  Scene m = hex8BenchmarkScene();
  for (auto& p : m.physics) p.mass = MassKind::Lumped;
  m.mask = Assembler::carriedComponents(m.mesh, m.physics);
  for (int n : m.mesh.findNodeSet("CL_POU2")->nodes) m.mask[n] &= std::uint8_t(~(1u << DZ));
  const std::vector<NodalSpring> springs{{m.mesh.findNodeSet("B")->nodes.front(), {0.6, 0.0, 0.8}, 1e12}};
  auto world = Teuchos::DefaultComm<int>::getComm();
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  DofMap dw(m.mask, world->getSize(), world->getRank()), ds(m.mask, 1, 0);
  const Assembler aw(m.mesh, dw, m.physics, world), as(m.mesh, ds, m.physics, self);
  for (const auto& sp : {std::vector<NodalSpring>{}, springs}) {
    const double w = aw.eigenvalueBound(sp), s1 = as.eigenvalueBound(sp);
    EXPECT_TRUE(std::isfinite(w) && w > 0);
    EXPECT_TRUE(sameBits(w, s1)) << w << " on " << world->getSize() << " ranks, " << s1 << " on one";
  }
}

}  // namespace
}  // namespace choc
