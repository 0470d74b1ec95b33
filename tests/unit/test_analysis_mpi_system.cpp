// The effective matrix of an implicit step with contact (EffectiveSystem with a contact strategy): its graph is built
// from K's and M's local arrays and its bulk values written through them, so the product
// A x is checked against aM M x + aK K x plus the contact block computed term by term, on
// non-matching faces (slave nodes coupled to master nodes of another body, on another rank
// under 2 ranks).
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
#include "physics/EffectiveSystem.hpp"
#include "physics/Model.hpp"
#include "test_analysis_contact_helpers.hpp"

namespace choc {
namespace {

// The two bars overlapping by 1e-7 m, 2 x 2 against 3 x 3 elements across (non-matching
// faces), and their contact pair by `method` (penalty 1e10 N/m per node, or Lagrange).
struct Scene {
  RCP<const Comm> comm = Tpetra::getDefaultComm();
  std::unique_ptr<Model> model;
  std::unique_ptr<ContactManager> cm;
  std::unique_ptr<ContactStrategy> strategy;  // penalty springs, or the multipliers' saddle point
  Scene(const std::string& name, const std::string& method) {
    const std::string dir = test::scratchDir(name + "_" + method + std::to_string(comm->getSize()));
    const std::string mesh = test::writeScene(dir, 0.1, 4, 2, 0.1, 4, 3, -1e-7, comm);
    auto d = test::readDeck(dir, test::deck(mesh, "CL_POU2", test::kModelOnlyAnalysis), comm);
    model = std::make_unique<Model>(*d.input, d.file, comm);
    cm = std::make_unique<ContactManager>(
        model->mesh(), model->dofs(), model->map(), std::vector<PairDefinition>{{"ifc", "CNT_POU1", "CNT_POU2", 1e-3}},
        method == "Penalty" ? makePenaltyContact(1e10, 1e-12) : makeLagrangeContact(1e-12));
    if (method == "Penalty")
      strategy = std::make_unique<PenaltyStrategy>(*cm);
    else
      strategy = std::make_unique<SaddlePointStrategy>(*cm);
  }
};

// 1 / (beta dt^2) at dt = 1e-6 s: the mass, stiffness and penalty parts of one size.
const double kAM = 4e12, kAK = 1.1;

// With every slave node in contact (the bars overlap by 1e-7 m): y = A [x; 0] on the DOF
// rows equals aM M x + aK K x + k sum_s b_s (b_s . x), and a multiplier row equals -S b_s . x.
void checkFill(const std::string& method) {
  Scene scene("system", method);
  Model& model = *scene.model;
  ContactManager& cm = *scene.cm;
  ContactStrategy& st = *scene.strategy;
  auto comm = scene.comm;
  Vector zero(model.map());
  st.initialize(zero);
  ASSERT_EQ(cm.activeCount(), cm.numConstraints());
  ASSERT_GT(cm.numConstraints(), 0);
  EffectiveSystem sys(model.stiffness(), model.mass(), &st);
  const double aM = kAM, aK = kAK;
  sys.fill(aM, aK);
  ASSERT_EQ(st.extendsSystem(), method != "Penalty");

  Vector X(sys.map()), Y(sys.map());
  X.randomize();
  {
    auto x = X.getDataNonConst();
    for (size_t i = model.map()->getNodeNumElements(); i < size_t(x.size()); ++i) x[i] = 0.0;
  }
  sys.matrix()->apply(X, Y);

  Vector x(model.map()), expected(model.map()), t(model.map());
  {
    auto xs = X.getData();
    auto xd = x.getDataNonConst();
    for (size_t i = 0; i < model.map()->getNodeNumElements(); ++i) xd[i] = xs[i];
  }
  model.mass()->apply(x, expected);
  model.stiffness()->apply(x, t);
  expected.update(aK, t, aM);
  // b_s . x over the ranks that own the terms' DOFs.
  const int nS = cm.numConstraints();
  std::vector<double> mine(nS, 0.0), bx(nS, 0.0);
  auto map = model.map();
  auto xd = x.getData();
  for (int s = 0; s < nS; ++s)
    for (const auto& [dof, c] : cm.constraints()[s].terms) {
      const LO l = map->getLocalElement(dof);
      if (l != Teuchos::OrdinalTraits<LO>::invalid()) mine[s] += c * xd[l];
    }
  Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_SUM, nS, mine.data(), bx.data());
  const double kc = cm.method().stiffness();
  {
    auto e = expected.getDataNonConst();
    for (int s = 0; s < nS; ++s)
      for (const auto& [dof, c] : cm.constraints()[s].terms) {
        const LO l = map->getLocalElement(dof);
        if (l != Teuchos::OrdinalTraits<LO>::invalid()) e[l] += kc * c * bx[s];
      }
  }
  double worst = 0.0, scale = expected.normInf();
  {
    auto y = Y.getData();
    auto e = expected.getData();
    for (size_t i = 0; i < model.map()->getNodeNumElements(); ++i) worst = std::max(worst, std::abs(y[i] - e[i]));
    for (int s = 0; s < nS; ++s) {
      const LO row = st.multiplierRow(s);
      if (row >= 0) EXPECT_NEAR(y[row], -cm.activeSet().scale * bx[s], 1e-12 * cm.activeSet().scale * std::abs(bx[s]) + 1e-300)
                        << method << ": multiplier row of slave " << s;
    }
  }
  double all = 0.0;
  Teuchos::reduceAll<int, double>(*comm, Teuchos::REDUCE_MAX, 1, &worst, &all);
  EXPECT_LE(all, 1e-13 * scale) << method << ": DOF rows of A x against aM M x + aK K x + contact";
}

// A refill after a change of statuses with the same (aM, aK) rewrites only the contact rows:
// A x equals, bit for bit, that of a system filled once for the new statuses.
void checkRefill(const std::string& method) {
  Scene scene("refill", method);
  Model& model = *scene.model;
  ContactManager& cm = *scene.cm;
  ContactStrategy& st = *scene.strategy;
  Vector u(model.map());
  st.initialize(u);  // all in contact
  const double aM = kAM, aK = kAK;
  EffectiveSystem kept(model.stiffness(), model.mass(), &st);
  kept.fill(aM, aK);
  // Bar 1 pulled back by 1e-6 m on its half x > 0 (across 2 elements): the slave nodes
  // facing it open, the others stay closed.
  {
    const NodeSet& pou1 = model.nodeSet("POU1", "test");
    for (int n : pou1.nodes)
      if (model.dofs().ownsNode(n) && model.mesh().coords[n][0] > 1e-9)
        u.replaceGlobalValue(GO(model.dof(n, 2)), 1e-6);
  }
  st.initialize(u);
  const int open = cm.numConstraints() - cm.activeCount();
  ASSERT_GT(open, 0);
  ASSERT_GT(cm.activeCount(), 0);
  for (int pass = 0; pass < 2; ++pass) {  // opened, then closed again
    kept.fill(aM, aK);
    EffectiveSystem fresh(model.stiffness(), model.mass(), &st);
    fresh.fill(aM, aK);
    Vector X(kept.map()), Y1(kept.map()), Y2(kept.map());
    X.randomize();
    kept.matrix()->apply(X, Y1);
    fresh.matrix()->apply(X, Y2);
    Y1.update(-1.0, Y2, 1.0);
    EXPECT_EQ(Y1.normInf(), 0.0) << method << ": pass " << pass;
    u.putScalar(0.0);
    st.initialize(u);
  }
}

TEST(MpiEffectiveSystem, PenaltyRefillRewritesTheContactRowsOnly) { checkRefill("Penalty"); }
TEST(MpiEffectiveSystem, LagrangeRefillRewritesTheContactRowsOnly) { checkRefill("Lagrange"); }

TEST(MpiEffectiveSystem, PenaltyFillIsTheMatricesPlusTheActiveCouplings) { checkFill("Penalty"); }
TEST(MpiEffectiveSystem, LagrangeFillIsTheMatricesPlusTheMultiplierBlock) { checkFill("Lagrange"); }

}  // namespace
}  // namespace choc
