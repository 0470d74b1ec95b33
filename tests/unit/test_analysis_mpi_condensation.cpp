// Contact multipliers condensed out of the Newton system (ContactCondensation): the compact
// block of input/compact_block.xml (10 x 10 x 10 HEX8, every component free) pressed into one
// or two tilted rigid planes, every node of its lower face in contact. The condensed matrix is
// symmetric, and its solution is the saddle-point system's: the same correction, the same
// pressures, the active gaps closed; with sliding friction too. Also on 2 ranks.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "contact/ContactStrategies.hpp"
#include "physics/EffectiveSystem.hpp"
#include "core/Errors.hpp"
#include "physics/Model.hpp"
#include "solvers/LinearSolver.hpp"
#include "test_analysis_contact_helpers.hpp"

namespace choc {
namespace {

struct Block {
  RCP<const Comm> comm = Tpetra::getDefaultComm();
  std::unique_ptr<Model> model;
  explicit Block(const std::string& name) {
    const std::string dir = test::scratchDir(name + std::to_string(comm->getSize()));
    std::ifstream in(std::string(CHOC_SOURCE_DIR) + "/input/compact_block.xml");
    std::stringstream ss;
    ss << in.rdbuf();
    std::string text = ss.str();
    const std::string mesh = "../meshes/compact_block.msh";
    text.replace(text.find(mesh), mesh.size(), std::string(CHOC_SOURCE_DIR) + "/meshes/compact_block.msh");
    auto d = test::readDeck(dir, text, comm);
    model = std::make_unique<Model>(*d.input, d.file, comm);
  }
  // The lower face against each plane (normal, point), Lagrange contact, friction mu.
  std::unique_ptr<ContactManager> manager(const std::vector<std::pair<Vec3, Vec3>>& planes, double mu = 0.0) const {
    std::vector<PairDefinition> pairs;
    for (size_t i = 0; i < planes.size(); ++i) {
      PairDefinition p;
      p.name = "plane" + std::to_string(i);
      p.slaveSideSet = "bottom";
      p.searchDistance = 1.0;
      p.hasObstacle = true;
      p.friction = mu;
      RigidObstacle o;
      o.direction = planes[i].first;
      o.point = planes[i].second;
      p.obstacle = validatedObstacle(o);
      pairs.push_back(p);
    }
    return std::make_unique<ContactManager>(model->mesh(), model->dofs(), model->map(), pairs,
                                            makeLagrangeContact(1e-12));
  }
};

// 1 / (beta dt^2) and 1 at dt = 1e-6 s.
const double kAM = 4e12, kAK = 1.0;

double maxOverRanks(const Comm& comm, double v) {
  double all = 0.0;
  Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_MAX, 1, &v, &all);
  return all;
}

void solve(EffectiveSystem& sys, const Vector& r, const Vector& u, Vector& du) {
  Teuchos::ParameterList p = linearSolverParameters();
  p.set("Method", "Direct");
  p.set("Direct Package", "KLU2");
  auto solver = makeLinearSolver(p);
  solver->setMatrix(sys.matrix());
  MultiVector b(sys.map(), 1), x(sys.map(), 1);
  sys.rightHandSide(r, u, b);
  const LinearSolveStatus st = solver->solve(b, x);
  ASSERT_TRUE(st.converged) << st.message;
  sys.takeSolution(x, du);
}

void checkCondensation(const std::vector<std::pair<Vec3, Vec3>>& planes, const std::string& name) {
  Block block(name);
  Model& model = *block.model;
  auto saddle = block.manager(planes), condensed = block.manager(planes);
  Vector u(model.map());
  SaddlePointStrategy saddleRows(*saddle);
  CondensedStrategy condensedRows(*condensed);
  saddleRows.initialize(u);
  condensedRows.initialize(u);
  ASSERT_GT(saddle->numConstraints(), 0);
  ASSERT_EQ(saddle->activeCount(), saddle->numConstraints()) << "every node pressed into every plane";
  EffectiveSystem ext(model.stiffness(), model.mass(), &saddleRows);
  EffectiveSystem con(model.stiffness(), model.mass(), &condensedRows);
  ASSERT_GT(ext.map()->getGlobalNumElements(), model.map()->getGlobalNumElements()) << "multiplier rows";
  ASSERT_EQ(con.map()->getGlobalNumElements(), model.map()->getGlobalNumElements()) << "condensed";
  ext.fill(kAM, kAK);
  con.fill(kAM, kAK);

  // Symmetric: (A x) . y = x . (A y).
  Vector X(con.map()), Y(con.map()), AX(con.map()), AY(con.map());
  X.randomize();
  Y.randomize();
  con.matrix()->apply(X, AX);
  con.matrix()->apply(Y, AY);
  EXPECT_LE(std::abs(AX.dot(Y) - X.dot(AY)), 1e-12 * AX.norm2() * Y.norm2()) << name;

  // A residual of force size: the same correction and pressures from both systems.
  Vector r(model.map()), due(model.map()), duc(model.map());
  r.randomize();
  r.scale(1e3);
  solve(ext, r, u, due);
  solve(con, r, u, duc);
  const double scale = due.normInf();
  duc.update(-1.0, due, 1.0);
  EXPECT_LE(duc.normInf(), 1e-9 * scale) << name << ": the condensed correction against the saddle point's";
  double worst = 0.0, peak = 0.0;
  for (int s = 0; s < saddle->numConstraints(); ++s) {
    worst = std::max(worst, std::abs(saddle->activeSet().lambda[s] - condensed->activeSet().lambda[s]));
    peak = std::max(peak, std::abs(saddle->activeSet().lambda[s]));
  }
  EXPECT_GT(peak, 0.0);
  EXPECT_LE(worst, 1e-9 * peak) << name << ": the pressures";
  // The active gaps closed at u + du to round-off of the gaps at u.
  duc.update(1.0, due, 1.0);
  const std::vector<double> g0 = condensed->gaps(u), g = condensed->gaps(duc);
  double before = 0.0, after = 0.0;
  for (size_t s = 0; s < g.size(); ++s) {
    before = std::max(before, std::abs(g0[s]));
    after = std::max(after, std::abs(g[s]));
  }
  EXPECT_LE(maxOverRanks(*block.comm, after), 1e-12 * before) << name;
}

// The planes pass above the lower face (z = 0, 0 <= x, y <= 0.1): every node penetrates.
TEST(MpiContactCondensation, OneTiltedPlaneGivesTheSaddlePointsCorrectionAndPressures) {
  checkCondensation({{{0.1, 0.05, 1.0}, {0, 0, 0.02}}}, "condensation_one");
}

TEST(MpiContactCondensation, TwoPlanesAtEveryNodeGiveTheSaddlePointsCorrectionAndPressures) {
  checkCondensation({{{0.1, 0.05, 1.0}, {0, 0, 0.02}}, {{-0.2, 0.1, 1.0}, {0, 0, 0.03}}}, "condensation_two");
}

// With Coulomb friction (mu = 0.3), the nodes sliding: the first correction gives the
// pressures (about 4e7 N), then the block is pushed along x by 1 mm, which makes the nodes slide
// (k_t = 1e12 N/m: 1e9 N against mu f_N); the
// friction tangent (not symmetric, with d force / d lambda in the multipliers' columns) is
// condensed with its multiplier column: the same correction and pressures as the saddle point.
TEST(MpiContactCondensation, SlidingFrictionGivesTheSaddlePointsCorrectionAndPressures) {
  Block block("condensation_friction");
  Model& model = *block.model;
  const std::vector<std::pair<Vec3, Vec3>> plane{{{0.1, 0.05, 1.0}, {0, 0, 0.02}}};
  auto saddle = block.manager(plane, 0.3), condensed = block.manager(plane, 0.3);
  Vector u(model.map()), r(model.map()), du(model.map());
  SaddlePointStrategy saddleRows(*saddle);
  CondensedStrategy condensedRows(*condensed);
  for (ContactStrategy* cs : {static_cast<ContactStrategy*>(&saddleRows), static_cast<ContactStrategy*>(&condensedRows)}) {
    cs->geometry().friction()->setTangentialStiffness(1e12);
    cs->beginStep(u, 1e-6, 1e-6);
    cs->initialize(u);
  }
  r.randomize();
  r.scale(1e3);
  EffectiveSystem ext(model.stiffness(), model.mass(), &saddleRows);
  EffectiveSystem con(model.stiffness(), model.mass(), &condensedRows);
  ext.fill(kAM, kAK);
  con.fill(kAM, kAK);
  solve(ext, r, u, du);  // the pressures (no friction force yet: lambda was 0)
  solve(con, r, u, du);
  // Pushed along x: the nodes slide.
  Vector push(model.map());
  for (int n = 0; n < model.mesh().numNodes(); ++n)
    if (model.dofs().ownsNode(n) && model.dof(n, 0) >= 0) push.replaceGlobalValue(GO(model.dof(n, 0)), 1e-3);
  Vector fe(model.map()), fc(model.map());
  saddle->addForces(push, fe);  // evaluates friction at push: sliding
  condensed->addForces(push, fc);
  int sliding = 0;
  for (char st : saddle->friction()->key()) sliding += st == 2;
  ASSERT_GT(sliding, 0) << "nodes sliding";
  ext.fill(kAM, kAK);
  con.fill(kAM, kAK);
  Vector due(model.map()), duc(model.map());
  solve(ext, r, push, due);
  solve(con, r, push, duc);
  const double scale = due.normInf();
  duc.update(-1.0, due, 1.0);
  EXPECT_LE(duc.normInf(), 1e-9 * scale) << "the condensed correction with friction";
  double worst = 0.0, peak = 0.0;
  for (int s = 0; s < saddle->numConstraints(); ++s) {
    worst = std::max(worst, std::abs(saddle->activeSet().lambda[s] - condensed->activeSet().lambda[s]));
    peak = std::max(peak, std::abs(saddle->activeSet().lambda[s]));
  }
  EXPECT_GT(peak, 0.0);
  EXPECT_LE(worst, 1e-9 * peak) << "the pressures with friction";
}

// Two planes with the same normal at a node: the constraints are dependent, which the
// saddle-point system cannot solve either; the condensation says so.
TEST(MpiContactCondensation, ParallelPlanesAtANodeAreANumericalError) {
  Block block("condensation_parallel");
  auto cm = block.manager({{{0, 0, 1}, {0, 0, 0.02}}, {{0, 0, 2}, {0, 0, 0.03}}});
  Vector u(block.model->map());
  CondensedStrategy rows(*cm);
  rows.initialize(u);
  EffectiveSystem con(block.model->stiffness(), block.model->mass(), &rows);
  EXPECT_THROW(con.fill(kAM, kAK), NumericalError);
}

}  // namespace
}  // namespace choc
