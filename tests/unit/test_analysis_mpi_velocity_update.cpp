// The contact velocity update ('Contact Mass' = velocity update, ContactStrategy::correctVelocity):
// after a step, every active constraint's gap rate and gap acceleration are brought to 0 by a
// projection in the mass's norm. With the lumped mass it moves v and a only along the
// constraints' rows and never raises the lumped kinetic energy; with the consistent mass it is
// M^-1 B^T lambda and never raises 1/2 v^T M v (by Pythagoras in M's norm, the energy taken is
// that of the change). Checked on non-matching faces (the slave nodes coupled to master nodes of
// the other bar, on another rank under 2 ranks), with some constraints open.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "contact/ContactStrategies.hpp"
#include "physics/MassDamping.hpp"
#include "physics/Model.hpp"
#include "test_analysis_contact_helpers.hpp"

namespace choc {
namespace {

// 1/2 v^T W^-1 v over the ranks, W the lumped inverse masses.
double lumpedKinetic(const Vector& v, const Vector& w) {
  auto vd = v.getData();
  auto wd = w.getData();
  double mine = 0.0, all = 0.0;
  for (size_t i = 0; i < v.getLocalLength(); ++i) mine += 0.5 * vd[i] * vd[i] / wd[i];
  Teuchos::reduceAll<int, double>(*v.getMap()->getComm(), Teuchos::REDUCE_SUM, 1, &mine, &all);
  return all;
}

// B_s x for every constraint (replicated).
std::vector<double> rows(const ContactManager& cm, const Vector& x) {
  const std::vector<double> values = cm.contactValues(x);
  std::vector<double> out(size_t(cm.numConstraints()), 0.0);
  for (int s = 0; s < cm.numConstraints(); ++s)
    for (const auto& [k, c] : cm.localTerms()[size_t(s)]) out[size_t(s)] += c * values[size_t(k)];
  return out;
}

// 1/2 v^T M v over the ranks.
double kinetic(const CrsMatrix& M, const Vector& v) {
  Vector Mv(v.getMap());
  M.apply(v, Mv);
  return 0.5 * v.dot(Mv);
}

// The scene of both tests: bar 1 pulled back by 1e-6 m on its half x > 0, so the slave nodes
// facing it open and the others stay closed.
struct Scene {
  std::unique_ptr<Model> model;
  std::unique_ptr<ContactManager> cm;
  std::unique_ptr<SaddlePointStrategy> strategy;
};

Scene scene(const std::string& name) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = test::scratchDir(name + std::to_string(comm->getSize()));
  const std::string mesh = test::writeScene(dir, 0.1, 4, 2, 0.1, 4, 3, -1e-7, comm);
  auto d = test::readDeck(dir, test::deck(mesh, "CL_POU2", test::kModelOnlyAnalysis), comm);
  Scene s;
  s.model = std::make_unique<Model>(*d.input, d.file, comm);
  const Model& model = *s.model;
  s.cm = std::make_unique<ContactManager>(model.mesh(), model.dofs(), model.map(),
                                          std::vector<PairDefinition>{{"ifc", "CNT_POU1", "CNT_POU2", 1e-3}},
                                          makeLagrangeContact(1e-12));
  s.strategy = std::make_unique<SaddlePointStrategy>(*s.cm);
  Vector u(model.map());
  for (int n : s.model->nodeSet("POU1", "test").nodes)
    if (model.dofs().ownsNode(n) && model.mesh().coords[n][0] > 1e-9) u.replaceGlobalValue(GO(model.dof(n, 2)), 1e-6);
  s.strategy->initialize(u);
  // Some constraints closed, some open.
  EXPECT_GT(s.cm->activeCount(), 0);
  EXPECT_LT(s.cm->activeCount(), s.cm->numConstraints());
  return s;
}

// Random v and a (a at 1e6 the scale of v), the fields before, and each constraint's rows.
struct Fields {
  Vector v, a, v0, a0;
  std::vector<double> rates0, acc0;
  Fields(const Model& model, const ContactManager& cm) : v(model.map()), a(model.map()), v0(model.map()), a0(model.map()) {
    v.randomize();
    a.randomize();
    a.scale(1e6);
    v0.assign(v);
    a0.assign(a);
    rates0 = rows(cm, v0);
    acc0 = rows(cm, a0);
  }
  // Every active constraint's gap rate and acceleration at rest, to 1e-10 of the largest before
  // (the solvers converge at 1e-12).
  void expectActiveRowsAtRest(const ContactManager& cm) const {
    const std::vector<double> rates = rows(cm, v), acc = rows(cm, a);
    double rateScale = 0.0, accScale = 0.0;
    for (int s = 0; s < cm.numConstraints(); ++s) {
      rateScale = std::max(rateScale, std::abs(rates0[size_t(s)]));
      accScale = std::max(accScale, std::abs(acc0[size_t(s)]));
    }
    for (int s = 0; s < cm.numConstraints(); ++s)
      if (cm.status()[size_t(s)]) {
        EXPECT_LE(std::abs(rates[size_t(s)]), 1e-10 * rateScale) << "active constraint " << s;
        EXPECT_LE(std::abs(acc[size_t(s)]), 1e-10 * accScale) << "active constraint " << s;
      }
  }
};

// 1 / (M 1): the lumped inverse masses.
Vector lumpedInverse(Model& model) {
  Vector w(model.map()), one(model.map());
  one.putScalar(1.0);
  model.mass()->apply(one, w);
  w.reciprocal(w);
  return w;
}

TEST(MpiVelocityUpdate, ConsistentMassProjectionBringsActiveRowsToRestAndTakesTheChangesEnergy) {
  Scene sc = scene("velocity_update_consistent");
  Model& model = *sc.model;
  const ContactManager& cm = *sc.cm;
  RCP<const CrsMatrix> M = model.mass();
  MassDamping mass(M, 0.0, 0.0, nullptr);
  Vector w(model.map());
  M->getLocalDiagCopy(w);
  w.reciprocal(w);
  Fields f(model, cm);
  ASSERT_TRUE(sc.strategy->correctVelocity(f.v, f.a, w, [&](const Vector& b, Vector& x) { mass.solveMass(b, x); }));
  f.expectActiveRowsAtRest(cm);
  // The projection in M's norm: 1/2 v0.M v0 - 1/2 v.M v = 1/2 dv.M dv (dv M-orthogonal to v),
  // to the solves' tolerance (1e-13 of the inner, 1e-12 of the outer residual).
  Vector dv(f.v, Teuchos::Copy);
  dv.update(-1.0, f.v0, 1.0);
  const double before = kinetic(*M, f.v0), after = kinetic(*M, f.v), change = kinetic(*M, dv);
  EXPECT_LT(after, before);
  EXPECT_GT(change, 0.0);
  EXPECT_NEAR(before - after, change, 1e-9 * before);
  // The lumped projection (a fresh strategy: the lumped masses are gathered once) is no
  // projection in M's norm: the identity fails by far more than the tolerance above, which is
  // why a lumped projection on a consistent mass could create energy (example 03: +1.9 % of E0).
  Scene lumped = scene("velocity_update_lumped_on_consistent");
  Vector v1(f.v0, Teuchos::Copy), a1(f.a0, Teuchos::Copy);
  ASSERT_TRUE(lumped.strategy->correctVelocity(v1, a1, lumpedInverse(model)));
  Vector dv1(v1, Teuchos::Copy);
  dv1.update(-1.0, f.v0, 1.0);
  EXPECT_GT(std::abs(before - kinetic(*M, v1) - kinetic(*M, dv1)), 1e-6 * before);
}

// With a direct linear solver the run solves M by its package (M factored once, kept: a
// third of the conjugate gradients' time on Hertz's two spheres). The solve is a direct one: its
// residual is at round-off (a mass matrix's condition number is tens), below the 1e-13 of |b|
// where conjugate gradients stop; the projection is the conjugate gradients' one to their tolerances (1e-13 inner,
// 1e-12 outer of the rows' scale).
TEST(MpiVelocityUpdate, ConsistentMassProjectionIsTheSameWithTheMassFactored) {
  Scene sc = scene("velocity_update_factored");
  Model& model = *sc.model;
  RCP<const CrsMatrix> M = model.mass();
  MassDamping iterative(M, 0.0, 0.0, nullptr), factored(M, 0.0, 0.0, nullptr);
  factored.solveMassBy("KLU2");
  Vector b(model.map()), x(model.map()), r(model.map());
  b.randomize();
  factored.solveMass(b, x);
  M->apply(x, r);
  r.update(-1.0, b, 1.0);
  EXPECT_LE(r.norm2(), 1e-14 * b.norm2());
  Vector w(model.map());
  M->getLocalDiagCopy(w);
  w.reciprocal(w);
  Fields f(model, *sc.cm);
  Vector v1(f.v0, Teuchos::Copy), a1(f.a0, Teuchos::Copy);
  ASSERT_TRUE(sc.strategy->correctVelocity(f.v, f.a, w, [&](const Vector& b, Vector& x) { iterative.solveMass(b, x); }));
  Scene again = scene("velocity_update_factored_again");
  ASSERT_TRUE(again.strategy->correctVelocity(v1, a1, w, [&](const Vector& b, Vector& x) { factored.solveMass(b, x); }));
  f.expectActiveRowsAtRest(*sc.cm);
  v1.update(-1.0, f.v, 1.0);
  a1.update(-1.0, f.a, 1.0);
  EXPECT_LE(v1.normInf(), 1e-10 * f.v0.normInf());
  EXPECT_LE(a1.normInf(), 1e-10 * f.a0.normInf());
}

TEST(MpiVelocityUpdate, ActiveGapRatesAndAccelerationsComeToRestWithoutRaisingTheKineticEnergy) {
  Scene sc = scene("velocity_update");
  Model& model = *sc.model;
  const ContactManager& cm = *sc.cm;
  const Vector w = lumpedInverse(model);
  Fields f(model, cm);
  ASSERT_TRUE(sc.strategy->correctVelocity(f.v, f.a, w)) << "active constraints: the fields are corrected";
  f.expectActiveRowsAtRest(cm);
  // A projection in W^-1's norm: the kinetic energy does not grow, and by Pythagoras the
  // energy taken is that of the change.
  Vector dv(f.v, Teuchos::Copy);
  dv.update(-1.0, f.v0, 1.0);
  const double before = lumpedKinetic(f.v0, w), after = lumpedKinetic(f.v, w), change = lumpedKinetic(dv, w);
  EXPECT_LT(after, before);
  EXPECT_NEAR(before - after, change, 1e-9 * before);
  // The DOFs of no active constraint keep their values.
  std::vector<char> touched(model.map()->getNodeNumElements(), 0);
  for (int s = 0; s < cm.numConstraints(); ++s)
    if (cm.status()[size_t(s)])
      for (const auto& [dof, c] : cm.constraints()[size_t(s)].terms) {
        const LO l = model.map()->getLocalElement(dof);
        if (l != Teuchos::OrdinalTraits<LO>::invalid()) touched[size_t(l)] = 1;
      }
  auto vd = f.v.getData();
  auto v0d = f.v0.getData();
  for (size_t i = 0; i < touched.size(); ++i)
    if (!touched[i]) EXPECT_EQ(vd[i], v0d[i]) << "local DOF " << i;
}

}  // namespace
}  // namespace choc
