// The structural model's internal force behind the operator (physics/InternalForce.hpp):
// LinearElasticForce is K u with the tangent K at every u (version 0), its energy 1/2 u.K u
// with or without the product given; and the operator's factorisation key includes the
// tangent's version: a model whose tangent changes at every call is refactored at every
// correction, a constant one once per coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include <Teuchos_ParameterList.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "physics/LinearElasticForce.hpp"
#include "physics/StructuralOperator.hpp"
#include "solvers/LinearSolver.hpp"
#include "symmetric_band_helpers.hpp"

namespace choc {
namespace {

RCP<CrsMatrix> identity(const RCP<const Map>& map) {
  auto M = rcp(new CrsMatrix(map, 1));
  for (size_t l = 0; l < map->getNodeNumElements(); ++l) {
    const GO g = map->getGlobalElement(LO(l));
    M->insertGlobalValues(g, Teuchos::tuple<GO>(g), Teuchos::tuple<double>(1.0));
  }
  M->fillComplete();
  return M;
}

void fill(Vector& x, double shift) {
  for (size_t l = 0; l < x.getLocalLength(); ++l)
    x.replaceLocalValue(LO(l), band::probe(x.getMap()->getGlobalElement(LO(l))) + shift);
}

// A linear model whose tangent "changes" at every call: its version counts the calls.
class CountingForce : public LinearElasticForce {
 public:
  using LinearElasticForce::LinearElasticForce;
  RCP<const CrsMatrix> tangent(const Vector& u) override {
    ++calls_;
    return LinearElasticForce::tangent(u);
  }
  long long tangentVersion() const override { return calls_; }
  bool linear() const override { return false; }

 private:
  long long calls_ = 0;
};

TEST(InternalForce, LinearElasticIsKuWithAConstantTangent) {
  auto K = band::bandMatrix(30, 2, band::noEdit);
  LinearElasticForce f(K);
  Vector u(K->getRowMap()), fu(K->getRowMap()), Ku(K->getRowMap()), d(K->getRowMap());
  fill(u, 0.0);
  f.internalForce(u, fu);
  K->apply(u, Ku);
  d.update(1.0, fu, -1.0, Ku, 0.0);
  EXPECT_EQ(d.normInf(), 0.0);  // the same CRS product
  EXPECT_EQ(f.tangent(u).get(), K.get());
  EXPECT_EQ(f.tangentVersion(), 0);
  EXPECT_TRUE(f.linear());
  const double given = f.strainEnergy(u, &Ku), computed = f.strainEnergy(u, nullptr);
  EXPECT_EQ(given, computed);
  EXPECT_NEAR(computed, 0.5 * u.dot(Ku), 1e-14 * std::fabs(computed));
  EXPECT_GT(f.termsNorm(u), 0.0);
}

int refactorizations(std::shared_ptr<InternalForce> model, const RCP<CrsMatrix>& K) {
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", "Direct");
  StructuralOperator op(model, identity(K->getRowMap()), 0.0, 0.0, nullptr, nullptr, nullptr,
                        makeLinearSolver(p), nullptr);
  Vector u(K->getRowMap()), r(K->getRowMap()), du(K->getRowMap());
  fill(u, 0.0);
  fill(r, 1.0);
  EffectiveCoefficients c;
  c.ca = 4e6;
  c.cd = 1.0;
  int refactored = 0;
  for (int i = 0; i < 3; ++i) {
    const CorrectionStatus st = op.solveCorrection(c, u, r, du);
    EXPECT_TRUE(st.ok) << st.message;
    refactored += st.refactored;
  }
  return refactored;
}

TEST(InternalForce, TheTangentsVersionIsPartOfTheFactorisationKey) {
  auto K = band::bandMatrix(30, 2, band::noEdit);
  EXPECT_EQ(refactorizations(std::make_shared<LinearElasticForce>(K), K), 1);
  EXPECT_EQ(refactorizations(std::make_shared<CountingForce>(K), K), 3);
}

}  // namespace
}  // namespace choc
