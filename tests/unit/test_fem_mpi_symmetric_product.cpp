// SymmetricProduct (run by ctest on 1 and on 2 ranks): K x from the diagonal and upper triangle
// of each rank's block plus the entries in other ranks' columns equals Tpetra's CRS product to
// round-off, and a matrix that is not symmetric keeps the CRS product on every rank.
//
// The two products sum each row in different orders, so they agree within Higham's bound for
// two summation orders of sum_j a_ij x_j with n terms: 2 gamma_n sum_j |a_ij x_j|,
// gamma_n = n u / (1 - n u), u = 2^-53 (Accuracy and Stability of Numerical Algorithms, 4.4).
#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <limits>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_Vector.hpp>

#include "fem/Assembler.hpp"
#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/SymmetricProduct.hpp"
#include "mesh/BarImpactMesh.hpp"

namespace choc {
namespace {

long long sumOverRanks(long long v) {
  long long s = 0;
  MPI_Allreduce(&v, &s, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return s;
}

double probe(GO g) { return std::sin(0.37 * double(g) + 0.1) + 0.01 * double(g % 7); }

// A symmetric band matrix of n rows and half-bandwidth w (a_ij = a_ji, a dominant diagonal),
// distributed in contiguous blocks: on 2 ranks the rows near the cut have columns on the other
// rank. `edit` may change entries before fillComplete (global row, column, value).
template <class Edit>
RCP<CrsMatrix> bandMatrix(GO n, int w, Edit edit) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  auto map = rcp(new Map(Tpetra::global_size_t(n), 0, comm));
  auto A = rcp(new CrsMatrix(map, size_t(2 * w + 2)));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO i = map->getGlobalElement(LO(l));
    std::vector<GO> cols;
    std::vector<double> vals;
    for (GO j = std::max<GO>(0, i - w); j <= std::min<GO>(n - 1, i + w); ++j) {
      const GO a = std::min(i, j), b = std::max(i, j);
      cols.push_back(j);
      vals.push_back(i == j ? 10.0 + 0.1 * double(i % 5) : -1.0 / double(1 + b - a) + 0.01 * std::sin(double(a + 3 * b)));
    }
    edit(i, cols, vals);
    A->insertGlobalValues(i, Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
  }
  A->fillComplete();
  return A;
}

// y = S x against A x, row by row within Higham's bound; returns the rows outside it (all ranks).
long long rowsOutsideRoundoff(const CrsMatrix& A, const SymmetricProduct& S) {
  const auto map = A.getRowMap();
  Vector x(map), yCrs(map), ySym(map);
  for (size_t l = 0; l < x.getLocalLength(); ++l) x.replaceLocalValue(LO(l), probe(map->getGlobalElement(LO(l))));
  A.apply(x, yCrs);
  ySym.putScalar(123.0);  // apply overwrites
  S.apply(x, ySym);
  auto a = yCrs.getData(), b = ySym.getData();
  const double u = std::numeric_limits<double>::epsilon() / 2;
  long long bad = 0;
  for (size_t l = 0; l < x.getLocalLength(); ++l) {
    const GO g = map->getGlobalElement(LO(l));
    const size_t n = A.getNumEntriesInGlobalRow(g);
    CrsMatrix::nonconst_global_inds_host_view_type cols("cols", n);
    CrsMatrix::nonconst_values_host_view_type vals("vals", n);
    size_t got = 0;
    A.getGlobalRowCopy(g, cols, vals, got);
    double absSum = 0.0;
    for (size_t k = 0; k < got; ++k) absSum += std::fabs(vals[k] * probe(cols[k]));
    const double bound = 2.0 * (double(got) * u / (1.0 - double(got) * u)) * absSum;
    if (!(std::fabs(a[l] - b[l]) <= bound) && ++bad <= 5)
      ADD_FAILURE() << "row " << g << ": symmetric " << b[l] << ", CRS " << a[l] << ", bound " << bound;
  }
  return sumOverRanks(bad);
}

void noEdit(GO, std::vector<GO>&, std::vector<double>&) {}

TEST(MpiSymmetricProduct, ABandMatrixAcrossRanksGivesTheCrsProduct) {
  auto A = bandMatrix(61, 4, noEdit);
  auto S = SymmetricProduct::build(*A);
  ASSERT_TRUE(S) << "a symmetric matrix is stored symmetrically";
  // Diagonal, upper triangle of the owned block and the other ranks' columns: on one rank
  // (61 + 61 * 4 - 10) entries, half of the 61 * 9 - 20 stored by the CRS matrix plus the diagonal.
  if (A->getComm()->getSize() == 1) EXPECT_EQ(S->storedEntries(), size_t(61 + 61 * 4 - 10));
  EXPECT_EQ(rowsOutsideRoundoff(*A, *S), 0);
}

TEST(MpiSymmetricProduct, TheHex8StiffnessGivesTheCrsProduct) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  Mesh mesh = generateBarImpactMesh(o);
  std::vector<BlockPhysics> physics(mesh.blocks.size());
  for (auto& p : physics) p.kernel = makeHex8(Material{2e11, 0.3, 7800.0});
  std::vector<std::uint8_t> mask = Assembler::carriedComponents(mesh, physics);
  for (int n : mesh.findNodeSet("CL_POU2")->nodes) mask[n] = 0;
  auto comm = Teuchos::DefaultComm<int>::getComm();
  DofMap dofs(mask, comm->getSize(), comm->getRank());
  auto K = Assembler(mesh, dofs, physics, comm).stiffness({});
  auto S = SymmetricProduct::build(*K);
  ASSERT_TRUE(S) << "linear elasticity's stiffness is symmetric";
  EXPECT_EQ(rowsOutsideRoundoff(*K, *S), 0);
}

// One entry of the last row off its transpose by 1e-9 of the row's scale (a thousand times the
// symmetry test's 1e-12): that rank finds it, and every rank keeps the CRS product (a product
// is collective).
TEST(MpiSymmetricProduct, AnAsymmetricEntryOnOneRankKeepsTheCrsProductEverywhere) {
  const GO n = 61;
  auto A = bandMatrix(n, 4, [&](GO i, std::vector<GO>& cols, std::vector<double>& vals) {
    if (i == n - 1) vals[0] += 1e-9 * 10.0;  // (60, 56)
  });
  EXPECT_FALSE(SymmetricProduct::build(*A));
  // Round-off asymmetry (1e-15 of the scale) is symmetric enough.
  auto B = bandMatrix(n, 4, [&](GO i, std::vector<GO>& cols, std::vector<double>& vals) {
    if (i == n - 1) vals[0] += 1e-15 * 10.0;
  });
  EXPECT_TRUE(SymmetricProduct::build(*B));
}

TEST(MpiSymmetricProduct, AnEntryWithoutItsTransposeKeepsTheCrsProduct) {
  const GO n = 61;
  auto A = bandMatrix(n, 4, [&](GO i, std::vector<GO>& cols, std::vector<double>& vals) {
    if (i == n - 1) cols.push_back(n - 10), vals.push_back(0.5);  // (60, 51) without (51, 60)
  });
  EXPECT_FALSE(SymmetricProduct::build(*A));
}

}  // namespace
}  // namespace choc
