// SymmetricProduct (run by ctest on 1 and on 2 ranks): K x from the diagonal and upper triangle
// of each rank's block plus the entries in other ranks' columns equals Tpetra's CRS product to
// round-off (Higham's bound, symmetric_band_helpers.hpp), a matrix that is not symmetric keeps
// the CRS product on every rank, and refill() takes new values on the same graph.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>

#include "fem/Assembler.hpp"
#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/SymmetricProduct.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "symmetric_band_helpers.hpp"

namespace choc {
namespace {

using band::bandMatrix;
using band::noEdit;

long long rowsOutsideRoundoff(const CrsMatrix& A, const SymmetricProduct& S) {
  return band::rowsOutsideRoundoff(A, [&](const Vector& x, Vector& y) { S.apply(x, y); });
}

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

// The band matrix with a column map of its own, listing the columns in descending order: each
// row's owned columns then come in descending owned index (not the usual layout), so the
// product is built by the general path, which sorts each row; and again on another graph.
TEST(MpiSymmetricProduct, AColumnMapInAnotherOrderGivesTheCrsProduct) {
  const GO n = 61;
  const int w = 4;
  auto B = bandMatrix(n, w, noEdit);
  const auto rowMap = B->getRowMap();
  std::vector<GO> colGids;
  for (size_t c = 0; c < B->getColMap()->getNodeNumElements(); ++c) colGids.push_back(B->getColMap()->getGlobalElement(LO(c)));
  std::sort(colGids.rbegin(), colGids.rend());
  auto colMap = rcp(new Map(Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid(),
                            Teuchos::ArrayView<const GO>(colGids), 0, rowMap->getComm()));
  auto A = rcp(new CrsMatrix(rowMap, colMap, size_t(2 * w + 2)));
  for (size_t l = 0; l < rowMap->getNodeNumElements(); ++l) {
    const GO g = rowMap->getGlobalElement(LO(l));
    const size_t cnt = B->getNumEntriesInGlobalRow(g);
    CrsMatrix::nonconst_global_inds_host_view_type cols("cols", cnt);
    CrsMatrix::nonconst_values_host_view_type vals("vals", cnt);
    size_t got = 0;
    B->getGlobalRowCopy(g, cols, vals, got);
    A->insertGlobalValues(g, got, vals.data(), cols.data());
  }
  A->fillComplete(rowMap, rowMap);
  auto S = SymmetricProduct::build(*A);
  ASSERT_TRUE(S);
  EXPECT_EQ(rowsOutsideRoundoff(*A, *S), 0);
  EXPECT_FALSE(SymmetricProduct::build(*B)->refill(*A)) << "the same entries under other column indices";
  A->resumeFill();
  A->scale(2.0);
  A->fillComplete(rowMap, rowMap);
  EXPECT_TRUE(S->refill(*A));
  EXPECT_EQ(rowsOutsideRoundoff(*A, *S), 0);
}

// A new effective matrix on the same graph, as the contact system makes one (resumeFill, new
// values, fillComplete): refill() takes the new values, symmetric ones, and refuses the others
// on every rank, and a matrix of another graph.
TEST(MpiSymmetricProduct, RefillTakesNewValuesOnTheSameGraph) {
  const GO n = 61;
  auto A = bandMatrix(n, 4, noEdit);
  auto S = SymmetricProduct::build(*A);
  ASSERT_TRUE(S);
  // Each rank edits its own rows: a_ii += 1 + i and a_{i,i+1} = a_{i+1,i} += 0.1 (i + 1).
  auto edit = [&](double asymmetry) {
    A->resumeFill();
    const auto map = A->getRowMap();
    for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
      const GO i = map->getGlobalElement(LO(l));
      std::vector<GO> cols{i};
      std::vector<double> vals{1.0 + double(i)};
      if (i + 1 < n) cols.push_back(i + 1), vals.push_back(0.1 * double(i + 1));
      if (i > 0) cols.push_back(i - 1), vals.push_back(0.1 * double(i) + (i == n - 1 ? asymmetry : 0.0));
      A->sumIntoGlobalValues(i, Teuchos::ArrayView<const GO>(cols), Teuchos::ArrayView<const double>(vals));
    }
    A->fillComplete();
  };
  edit(0.0);
  EXPECT_TRUE(S->refill(*A));
  EXPECT_EQ(rowsOutsideRoundoff(*A, *S), 0) << "the product is the new matrix's";
  edit(1e-9 * 10.0);  // a_{60,59} off its transpose by 1e-9 of the row's scale, on the last rank
  EXPECT_FALSE(S->refill(*A));
  auto narrower = bandMatrix(n, 3, noEdit);
  EXPECT_FALSE(S->refill(*narrower)) << "another graph";
}

}  // namespace
}  // namespace choc
