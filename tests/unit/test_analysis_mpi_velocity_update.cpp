// The contact velocity update ('Contact Mass' = velocity update, ContactStrategy::correctVelocity):
// after a step, every active constraint's gap rate and gap acceleration are brought to 0 by a
// projection in the lumped mass's norm, which moves v and a only along the constraints' rows and
// never raises the lumped kinetic energy. Checked on non-matching faces (the slave nodes coupled
// to master nodes of the other bar, on another rank under 2 ranks), with some constraints open.
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

TEST(MpiVelocityUpdate, ActiveGapRatesAndAccelerationsComeToRestWithoutRaisingTheKineticEnergy) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = test::scratchDir("velocity_update" + std::to_string(comm->getSize()));
  const std::string mesh = test::writeScene(dir, 0.1, 4, 2, 0.1, 4, 3, -1e-7, comm);
  auto d = test::readDeck(dir, test::deck(mesh, "CL_POU2", test::kModelOnlyAnalysis), comm);
  Model model(*d.input, d.file, comm);
  ContactManager cm(model.mesh(), model.dofs(), model.map(), {{"ifc", "CNT_POU1", "CNT_POU2", 1e-3}},
                    makeLagrangeContact(1e-12));
  SaddlePointStrategy strategy(cm);
  // Bar 1 pulled back by 1e-6 m on its half x > 0: the slave nodes facing it open.
  Vector u(model.map());
  for (int n : model.nodeSet("POU1", "test").nodes)
    if (model.dofs().ownsNode(n) && model.mesh().coords[n][0] > 1e-9) u.replaceGlobalValue(GO(model.dof(n, 2)), 1e-6);
  strategy.initialize(u);
  const int active = cm.activeCount();
  ASSERT_GT(active, 0);
  ASSERT_LT(active, cm.numConstraints());

  Vector w(model.map()), one(model.map());
  one.putScalar(1.0);
  model.mass()->apply(one, w);
  w.reciprocal(w);
  Vector v(model.map()), a(model.map());
  v.randomize();
  a.randomize();
  a.scale(1e6);
  const Vector v0(v, Teuchos::Copy), a0(a, Teuchos::Copy);
  const std::vector<double> rates0 = rows(cm, v0), acc0 = rows(cm, a0);
  ASSERT_TRUE(strategy.correctVelocity(v, a, w)) << "active constraints: the fields are corrected";

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
  // A projection in W^-1's norm: the kinetic energy does not grow, and by Pythagoras the
  // energy taken is that of the change.
  Vector dv(v, Teuchos::Copy);
  dv.update(-1.0, v0, 1.0);
  const double before = lumpedKinetic(v0, w), after = lumpedKinetic(v, w), change = lumpedKinetic(dv, w);
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
  auto vd = v.getData();
  auto v0d = v0.getData();
  for (size_t i = 0; i < touched.size(); ++i)
    if (!touched[i]) EXPECT_EQ(vd[i], v0d[i]) << "local DOF " << i;
}

}  // namespace
}  // namespace choc
