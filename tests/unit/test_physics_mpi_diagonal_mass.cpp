// StructuralOperator with a lumped mass given as its diagonal (useDiagonalMass, explicit runs),
// on 1 and 2 ranks: applyForces' K u + aK K v + aM M v and the kinetic energy equal the same
// operator's with M's CRS product, with and without the products kept for the energies (the
// damping term is added in the residual's pass only when they are not kept).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <Teuchos_DefaultComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "physics/LinearElasticForce.hpp"
#include "physics/StructuralOperator.hpp"
#include "solvers/LinearSolver.hpp"
#include "symmetric_band_helpers.hpp"

namespace choc {
namespace {

double massOf(GO g) { return 1.0 + 0.25 * double(g % 3); }

RCP<CrsMatrix> diagonalMatrix(const RCP<const Map>& map) {
  auto M = rcp(new CrsMatrix(map, 1));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO g = map->getGlobalElement(LO(l));
    M->insertGlobalValues(g, Teuchos::tuple<GO>(g), Teuchos::tuple<double>(massOf(g)));
  }
  M->fillComplete();
  return M;
}

// The largest |a - b| over |scale| across ranks, entry by entry.
double worstRelative(const Vector& a, const Vector& b, const Vector& scale) {
  auto x = a.getData(), y = b.getData(), s = scale.getData();
  double local = 0.0;
  for (size_t l = 0; l < a.getLocalLength(); ++l) local = std::max(local, std::fabs(x[l] - y[l]) / s[l]);
  double global = 0.0;
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
  return global;
}

TEST(MpiDiagonalMass, ForcesAndKineticEnergyEqualTheCrsMass) {
  const double aK = 1e-3, aM = 0.7;
  auto K = band::bandMatrix(41, 3, band::noEdit);
  auto M = diagonalMatrix(K->getRowMap());
  auto m = rcp(new Vector(K->getRowMap()));
  M->getLocalDiagCopy(*m);
  auto uOf = [](GO g) { return band::probe(g); };
  auto vOf = [](GO g) { return 50.0 * band::probe(g + 17); };
  Vector u(K->getRowMap()), v(K->getRowMap()), absSum(K->getRowMap());
  for (size_t l = 0; l < u.getLocalLength(); ++l) {
    const GO g = K->getRowMap()->getGlobalElement(LO(l));
    u.replaceLocalValue(LO(l), uOf(g));
    v.replaceLocalValue(LO(l), vOf(g));
    // The entry's scale: sum_j |k_ij| (|u_j| + aK |v_j|) + aM m_i |v_i| bounds its sum's terms.
    const size_t n = K->getNumEntriesInGlobalRow(g);
    CrsMatrix::nonconst_global_inds_host_view_type cols("cols", n);
    CrsMatrix::nonconst_values_host_view_type vals("vals", n);
    size_t got = 0;
    K->getGlobalRowCopy(g, cols, vals, got);
    double s = aM * massOf(g) * std::fabs(vOf(g));
    for (size_t k = 0; k < got; ++k) s += std::fabs(vals[k]) * (std::fabs(uOf(cols[k])) + aK * std::fabs(vOf(cols[k])));
    absSum.replaceLocalValue(LO(l), s);
  }
  for (bool keep : {false, true}) {
    StructuralOperator crs(std::make_shared<LinearElasticForce>(K), M, aK, aM, nullptr, nullptr, nullptr, nullptr, nullptr);
    StructuralOperator diagonal(std::make_shared<LinearElasticForce>(K), M, aK, aM, nullptr, nullptr, nullptr, nullptr, nullptr);
    diagonal.useDiagonalMass(m);
    crs.keepProducts(keep);
    diagonal.keepProducts(keep);
    Vector a(K->getRowMap()), b(K->getRowMap());
    for (int call = 0; call < 2; ++call) {  // the second reuses the operator's buffers
      crs.applyForces(u, v, 0.0, a);
      diagonal.applyForces(u, v, 0.0, b);
    }
    // Two orders of the same three-term sum with one product each: a few units of round-off.
    EXPECT_LE(worstRelative(a, b, absSum), 8 * std::numeric_limits<double>::epsilon()) << "kept " << keep;
    diagonal.mass().kineticEnergy(v);
    const double ek = crs.mass().kineticEnergy(v), ed = diagonal.mass().kineticEnergy(v);
    EXPECT_NEAR(ed, ek, 1e-14 * ek) << "kept " << keep;
  }
}

}  // namespace
}  // namespace choc
