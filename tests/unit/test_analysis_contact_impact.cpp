// Contact with the implicit transient analysis: static compression against its closed form
// for the three methods (matching and non-matching faces), blocks dropped on a rigid base
// and on another block, and the three methods on the SDNL111 3D scene.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "analysis/DirectTransient.hpp"
#include "physics/LinearElasticForce.hpp"
#include "physics/StructuralOperator.hpp"
#include "contact/ContactManager.hpp"
#include "contact/ContactStrategies.hpp"
#include "reference/BarImpactExact.hpp"
#include "test_analysis_contact_helpers.hpp"
#include "timeint/NewtonActiveSet.hpp"

namespace choc {
namespace {

using test::deck;
using test::readDeck;
using test::scratchDir;
using test::writeScene;

const double kE = 2e11, kNu = 0.3, kRho = 7800, kArea = 4e-4;
const double kCp = std::sqrt(kE * (1 - kNu) / (kRho * (1 + kNu) * (1 - 2 * kNu)));

std::string transient(const std::string& name, const std::string& method, const std::string& scheme,
                      double alpha, double dt, double end, const std::string& extra = "",
                      const std::string& master = "CNT_POU1", const std::string& slave = "CNT_POU2") {
  std::ostringstream x;
  x << "<ParameterList name=\"" << name << "\">\n"
    << "<Parameter name=\"Type\" type=\"string\" value=\"Transient\"/>\n"
    << "<Parameter name=\"Scheme\" type=\"string\" value=\"" << scheme << "\"/>\n"
    << "<Parameter name=\"Alpha\" type=\"double\" value=\"" << alpha << "\"/>\n"
    << "<Parameter name=\"Time Step\" type=\"double\" value=\"" << dt << "\"/>\n"
    << "<Parameter name=\"End Time\" type=\"double\" value=\"" << end << "\"/>\n"
    << "<Parameter name=\"Exodus Interval\" type=\"int\" value=\"0\"/>\n"
    << "<ParameterList name=\"Contact\"><Parameter name=\"Method\" type=\"string\" value=\"" << method
    << "\"/><ParameterList name=\"Pairs\"><ParameterList name=\"ifc\">"
    << "<Parameter name=\"Master Side Set\" type=\"string\" value=\"" << master << "\"/>"
    << "<Parameter name=\"Slave Side Set\" type=\"string\" value=\"" << slave << "\"/>"
       "</ParameterList></ParameterList></ParameterList>\n"
    << "<ParameterList name=\"Initial Conditions\"><ParameterList name=\"v0\">"
       "<Parameter name=\"Node Set\" type=\"string\" value=\"POU1\"/>"
       "<Parameter name=\"Components\" type=\"string\" value=\"DZ\"/>"
       "<Parameter name=\"Value\" type=\"double\" value=\"-1\"/></ParameterList></ParameterList>\n"
    << "<Parameter name=\"History\" type=\"string\" value=\"N1:DZ N1:VZ\"/>\n"
    << extra << "</ParameterList>\n";
  return x.str();
}

struct RunResult {
  HistoryTable h;
  DirectTransient::Figures figures;
};

// Runs every analysis of the deck on `comm`; returns the history of `name`.
RunResult runDeck(const std::string& dir, const std::string& text, const std::string& name,
            RCP<const Comm> comm = Tpetra::getDefaultComm()) {
  auto d = readDeck(dir, text, comm);
  Model model(*d.input, d.file, comm);
  auto analyses = createAnalyses(d.input->sublist("Analyses"), d.file);
  setupAnalyses(analyses, model);
  RunContext ctx{model, dir, {}, {}};
  RunResult r;
  for (auto& a : analyses) {
    a->run(ctx);
    if (a->name() == name) r.figures = dynamic_cast<DirectTransient&>(*a).figures();
  }
  comm->barrier();
  r.h = readHistoryCsv(dir + "/" + name + ".history.csv");
  return r;
}

// Static compression: bar 1 (free, 1 x 1 across) pushed onto bar 2 (clamped at its far
// face, n x n across) by a total force F spread equally over bar 1's nodes. Lateral motion
// is blocked, so the stress is uniform: every slave node carries p = F / A times its area.
void staticCompression(const std::string& method, int across2, bool exactPressure) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratchDir("static_" + method + std::to_string(across2));
  // A small initial overlap (1e-7 m) closes the contact from the start (bar 1 is free).
  const std::string mesh = writeScene(dir, 0.1, 5, 1, 0.1, 5, across2, -1e-7, comm);
  auto d = readDeck(dir, deck(mesh, "CL_POU2", transient("s", method, "average acceleration", 0, 1e-6, 1e-6)), comm);
  Model model(*d.input, d.file, comm);
  const double F = 1e5, EN = 1e10;
  std::unique_ptr<ContactMethod> m = method == "Lagrange" ? makeLagrangeContact(1e-12)
                                     : method == "Penalty" ? makePenaltyContact(EN, 1e-12)
                                                           : makeAugmentedLagrangianContact(EN, 1e-12);
  ContactManager cm(model.mesh(), model.dofs(), model.map(), {{"ifc", "CNT_POU1", "CNT_POU2", 1e-3}},
                    std::move(m));
  auto load = rcp(new Vector(model.map()));
  const NodeSet& pou1 = model.nodeSet("POU1", "test");
  for (int n : pou1.nodes)
    if (model.dofs().ownsNode(n)) load->sumIntoGlobalValue(GO(model.dof(n, 2)), -F / pou1.nodes.size());
  Teuchos::ParameterList lsp = linearSolverParameters();
  auto loads = std::make_shared<Loads>();
  loads->add({"load", load, 0.0});
  // A direct solver: the multipliers on rows of their own (penalty: springs).
  ContactSettings cs;
  cs.method = method == "Lagrange" ? ContactMethodKind::Lagrange
              : method == "Penalty" ? ContactMethodKind::Penalty
                                    : ContactMethodKind::Continuous;
  std::unique_ptr<ContactStrategy> strategy = makeContactStrategy(cs, cm, {false, "Direct", "None"});
  StructuralOperator op(std::make_shared<LinearElasticForce>(model.stiffness()), model.mass(), 0, 0, loads,
                        strategy.get(), nullptr, makeLinearSolver(lsp), nullptr);
  Vector u(model.map());
  op.initializeConstraints(u);
  ASSERT_EQ(cm.activeCount(), cm.numConstraints());
  NewtonSettings ns;
  const NewtonOutcome out = solveStatic(op, u, 0.0, ns);
  ASSERT_TRUE(out.converged) << out.message;
  {
    // The strain energy reuses the last residual's K u for that u only (round-off of the dot).
    Vector Ku(model.map()), zero(model.map()), r(model.map()), u2(u, Teuchos::Copy);
    model.stiffness()->apply(u, Ku);
    const double direct = 0.5 * u.dot(Ku);
    EXPECT_NEAR(op.strainEnergy(u), direct, 1e-12 * direct) << method;  // u: Newton's last residual
    u2.scale(2.0);
    op.applyForces(u2, zero, 0.0, r);
    EXPECT_NEAR(op.strainEnergy(u), direct, 1e-12 * direct) << method;  // another u: computed again
    EXPECT_NEAR(op.strainEnergy(u2), 4 * direct, 4e-12 * direct) << method;
  }
  const auto f = cm.forces(u);
  const auto g = cm.gaps(u);
  double total = 0;
  for (double x : f) total += x;
  EXPECT_NEAR(total, F, 1e-8 * F) << method;  // equilibrium, any method
  const double p = F / kArea;
  const double delta = F * 0.1 / (kE * (1 - kNu) / ((1 + kNu) * (1 - 2 * kNu)) * kArea);  // bar 2 shortening
  for (int s = 0; s < cm.numConstraints(); ++s) {
    const double ps = f[s] / cm.constraints()[s].geometry.area;
    if (exactPressure) EXPECT_NEAR(ps, p, 1e-8 * p) << method << " node " << s;
    if (method == "Penalty") {
      // Penalty compliance: each node penetrates by its force over E_N.
      EXPECT_NEAR(-g[s], f[s] / EN, 1e-8 * f[s] / EN);
    } else {
      EXPECT_LE(std::abs(g[s]), 1e-9 * delta) << method << ": penetration";  // zero to solver tolerance
    }
  }
  if (!exactPressure) {
    // Penalty on non-matching faces: per-node springs on unequal areas tilt the pressure by
    // at most the compliance ratio (spring penetration against the bars' shortening).
    for (int s = 0; s < cm.numConstraints(); ++s) {
      const double ps = f[s] / cm.constraints()[s].geometry.area;
      EXPECT_NEAR(ps, p, p * (F / EN) / delta) << method << " node " << s;
    }
  }
}

TEST(ContactStatic, ThreeMethodsGiveTheClosedFormPressureOnMatchingFaces) {
  for (const char* m : {"Lagrange", "Penalty", "Continuous"}) staticCompression(m, 1, true);
}

TEST(ContactStatic, NonMatchingFacesCarryTheUniformPressure) {
  for (int n : {2, 3}) {
    staticCompression("Lagrange", n, true);
    staticCompression("Continuous", n, true);
    staticCompression("Penalty", n, false);
  }
}

double meanForceWhileClosed(const HistoryTable& h, const std::string& col, double& duration) {
  const auto t = h.column("time"), f = h.column(col);
  double sum = 0, first = -1, last = -1;
  for (size_t i = 1; i < t.size(); ++i)
    if (f[i] > 0) {
      sum += f[i] * (t[i] - t[i - 1]);
      if (first < 0) first = t[i - 1];
      last = t[i];
    }
  duration = last - first;
  return sum / duration;
}

// A 0.1 m block at 1 m/s onto a rigid base (bar 2 clamped everywhere): force rho c S |v0|
// for 2 L / c, then the block leaves at +|v0| (elastic rebound). The rigid base is the
// master surface (its nodes carry no unknowns; a finer rigid slave would over-constrain the
// block's face). Modified average acceleration alpha = -0.3: see the report on alpha = -0.1.
TEST(ContactImpact, BlockDroppedOnRigidBase) {
  for (int across2 : {1, 2}) {
    auto comm = Tpetra::getDefaultComm();
    const std::string dir = scratchDir("rigid" + std::to_string(across2));
    const double L = 0.1, dt = 2e-7, T = 2 * L / kCp;
    const std::string mesh = writeScene(dir, L, 20, 1, 0.05, 2, across2, 1e-5, comm);
    const RunResult r = runDeck(dir, deck(mesh, "POU2", transient("drop", "Lagrange", "modified average acceleration", -0.3, dt, 1e-5 + 1.5 * T, "", "CNT_POU2", "CNT_POU1")), "drop");
    double duration = 0;
    const double F = meanForceWhileClosed(r.h, "ifc:force", duration);
    // 5 %: the document's tolerance for these impacts (dispersion of the discrete wave).
    EXPECT_NEAR(F, kRho * kCp * kArea * 1.0, 0.05 * kRho * kCp * kArea) << across2;
    EXPECT_NEAR(duration, T, 0.05 * T) << across2;
    const auto gap = r.h.column("ifc:gap");
    EXPECT_GE(*std::min_element(gap.begin(), gap.end()), -1e-12) << "Lagrange: no penetration";
    // Momentum: the mean velocity of the block after the impact (from the impulse). The
    // dissipative scheme may lose energy, never gain it: at most +|v0|; at least the product
    // of the two 5 % tolerances above below it.
    const double mass = kRho * kArea * L, impulse = F * duration;
    EXPECT_LE(-1.0 + impulse / mass, 1.0 + 1e-3) << across2;
    EXPECT_GE(-1.0 + impulse / mass, 2 * 0.95 * 0.95 - 1.0) << across2;
  }
}

// A block onto another block (clamped at its far end): the d'Alembert solution, on matching
// and non-matching faces, for every method.
TEST(ContactImpact, BlockDroppedOnAnotherBlockFollowsTheExactSolution) {
  auto comm = Tpetra::getDefaultComm();
  for (int across2 : {1, 2}) {
    for (const char* method : {"Lagrange", "Penalty", "Continuous"}) {
      const std::string dir = scratchDir(std::string("block_") + method + std::to_string(across2));
      const double L = 0.1, dt = 2e-7, T = 2 * L / kCp;
      const std::string mesh = writeScene(dir, L, 20, 1, L, 20, across2, 1e-5, comm);
      const std::string exact =
          "<ParameterList name=\"Checks\"><ParameterList name=\"exact\">"
          "<Parameter name=\"Type\" type=\"string\" value=\"Bar Impact Exact Solution\"/>"
          "<Parameter name=\"Node Set\" type=\"string\" value=\"N1\"/><Parameter name=\"Component\" type=\"string\" value=\"DZ\"/>"
          "<Parameter name=\"Wave Speed\" type=\"string\" value=\"oedometric\"/>"
          "<Parameter name=\"Length\" type=\"double\" value=\"0.1\"/>"
          "<Parameter name=\"Contact Start\" type=\"double\" value=\"1e-5\"/>"
          "<Parameter name=\"Max Error Tolerance\" type=\"double\" value=\"0.05\"/></ParameterList></ParameterList>";
      auto d = readDeck(dir, deck(mesh, "CL_POU2", transient("b", method, "modified average acceleration", -0.3, dt, 1e-5 + 2.5 * T, exact)), comm);
      Model model(*d.input, d.file, comm);
      auto analyses = createAnalyses(d.input->sublist("Analyses"), d.file);
      setupAnalyses(analyses, model);
      RunContext ctx{model, dir, {}, {}};
      analyses[0]->run(ctx);
      ASSERT_EQ(ctx.checks.size(), 1u);
      EXPECT_TRUE(ctx.checks[0].ok) << method << " across2 " << across2 << ": max error/peak "
                                    << ctx.checks[0].computed;
      double duration = 0;
      const HistoryTable h = readHistoryCsv(dir + "/b.history.csv");
      const double F = meanForceWhileClosed(h, "ifc:force", duration);
      EXPECT_NEAR(F, 0.5 * kRho * kCp * kArea, 0.05 * 0.5 * kRho * kCp * kArea) << method;
      EXPECT_NEAR(duration, 2 * T, 0.05 * 2 * T) << method;
    }
  }
}

// Mass redistribution (Khenous, Laborde, Renard 2008) on the block-on-block impact with the
// average-acceleration rule (alpha = 0, no damping). With massless contact nodes every row
// holds M a_k = -K u_k + B^T lambda_k at each step k (g = g0 + B u; the contact rows carry no
// inertia and are equilibrated statically), and the trapezoidal relations give exactly
//   E_{k+1} - E_k = 1/2 (lambda_k + lambda_{k+1}) . (g_{k+1} - g_k),   E = 1/2 v.Mv + 1/2 u.Ku.
// With lambda g = 0 at each node this is 0 while the contact stays open or stays closed, and
// -1/2 lambda_{k+1} g_k <= 0 on the closing step, 1/2 lambda_k g_{k+1} >= 0 on the opening
// one (the work of the force over the gap closed or opened within the step). The faces match and move as one (lateral motion fixed), so every slave node has the
// pair's gap and the per-pair force and gap of the history give the identity exactly. The
// Newton residual (1e-8 of the largest force vector) adds at most that fraction of the work
// of the largest force over a step: bounded by 1e-8 * |F|max * |du|max * nodes per step,
// below 1e-12 E0 here; the test allows 1e-9 E0 per step for it (round-off included).
TEST(ContactImpact, RedistributedMassKeepsTheEnergyAndStopsTheChatter) {
  auto comm = Tpetra::getDefaultComm();
  for (const char* method : {"Lagrange", "Continuous"}) {
    const std::string dir = scratchDir(std::string("redistributed_") + method);
    const double L = 0.1, dt = 2e-7, T = 2 * L / kCp;
    const std::string mesh = writeScene(dir, L, 20, 1, L, 20, 1, 1e-5, comm);
    const std::string extra = "<Parameter name=\"Contact Mass\" type=\"string\" value=\"redistributed\"/>";
    const RunResult r = runDeck(dir, deck(mesh, "CL_POU2",
                                          transient("rd", method, "average acceleration", 0.0, dt,
                                                    1e-5 + 3 * T, extra)), "rd");
    const auto t = r.h.column("time"), E = r.h.column("energy:total");
    const auto F = r.h.column("ifc:force"), g = r.h.column("ifc:gap");
    const double E0 = 0.5 * kRho * kArea * L * 1.0;  // the block's kinetic energy
    EXPECT_NEAR(E[0], E0, 1e-12 * E0) << method << ": redistribution keeps the block's mass";
    int closings = 0, openings = 0;
    double bound = 0;
    for (size_t k = 0; k + 1 < t.size(); ++k) {
      const double identity = 0.5 * (F[k] + F[k + 1]) * (g[k + 1] - g[k]);
      EXPECT_NEAR(E[k + 1] - E[k], identity, 1e-9 * E0) << method << " step " << k + 1;
      bound += std::abs(identity);
      closings += F[k] == 0 && F[k + 1] > 0;
      openings += F[k] > 0 && F[k + 1] == 0;
    }
    // One impact: the contact closes once and opens once (no chatter), and the energy changes
    // only on those two steps, by at most the work of the force over the last open gap.
    EXPECT_EQ(closings, 1) << method;
    EXPECT_EQ(openings, 1) << method;
    EXPECT_LE(std::abs(E.back() - E0), bound + 1e-9 * E0 * double(t.size())) << method;
    EXPECT_LE(bound, 0.02 * E0) << method << ": the closing/opening work stays small";
    // While closed, the faces stay together: no relative velocity at the interface.
    double gapClosed = 0;
    for (size_t k = 0; k < t.size(); ++k)
      if (F[k] > 0) gapClosed = std::max(gapClosed, std::abs(g[k]));
    EXPECT_LE(gapClosed, 1e-12) << method;
    // The active set changed at most a few times (closing, opening, one confirming pass each).
    EXPECT_LE(r.figures.activeSetIterations - r.figures.steps, 4) << method;
    // And the d'Alembert force Z |v0| / 2 for 2 L / c.
    double duration = 0;
    const double Fm = meanForceWhileClosed(r.h, "ifc:force", duration);
    EXPECT_NEAR(Fm, 0.5 * kRho * kCp * kArea, 0.05 * 0.5 * kRho * kCp * kArea) << method;
    EXPECT_NEAR(duration, 2 * T, 0.05 * 2 * T) << method;
  }
}

// The SDNL111 scene with the three methods under the same scheme: Lagrange and continuous
// are the same constraint (identical to solver tolerance), penalty differs by its compliance.
TEST(ContactImpact, ThreeMethodsAgreeOnTheBenchmarkWithinThePenaltyCompliance) {
  auto comm = Tpetra::getDefaultComm();
  const std::string dir = scratchDir("sdnl111_three");
  const std::string mesh = std::string(CHOC_SOURCE_DIR) + "/meshes/sdnl111_3d.exo";
  const double EN = 1e10;
  std::string an;
  for (const char* m : {"Lagrange", "Penalty", "Continuous"})
    an += transient(m, m, "modified average acceleration", -0.3, 1e-6, 1e-3);
  auto d = readDeck(dir, deck(mesh, "CL_POU2", an), comm);
  Model model(*d.input, d.file, comm);
  auto analyses = createAnalyses(d.input->sublist("Analyses"), d.file);
  setupAnalyses(analyses, model);
  RunContext ctx{model, dir, {}, {}};
  for (auto& a : analyses) a->run(ctx);
  const HistoryTable lag = readHistoryCsv(dir + "/Lagrange.history.csv");
  const HistoryTable pen = readHistoryCsv(dir + "/Penalty.history.csv");
  const HistoryTable con = readHistoryCsv(dir + "/Continuous.history.csv");
  const auto ul = lag.column("N1:DZ"), up = pen.column("N1:DZ"), uc = con.column("N1:DZ");
  const auto fp = pen.column("ifc:force");
  const double compliance = *std::max_element(fp.begin(), fp.end()) / (4 * EN);  // per-node penetration
  double dLC = 0, dLP = 0;
  for (size_t i = 0; i < ul.size(); ++i) {
    dLC = std::max(dLC, std::abs(ul[i] - uc[i]));
    dLP = std::max(dLP, std::abs(ul[i] - up[i]));
  }
  EXPECT_LT(dLC, 1e-9 * 3e-4) << "Lagrange and continuous enforce the same constraint";
  EXPECT_LT(dLP, 2 * compliance) << "penalty: within its compliance " << compliance;
  EXPECT_GT(dLP, 0.0);
}

}  // namespace
}  // namespace choc

namespace choc {
namespace {

// Newton 'Convergence' = 'residual' drops the solve that only confirms a converged iterate.
// Within an active-set pass the step is linear (linear elasticity, contact status frozen), so
// one exact (direct) correction solves it: the histories must agree with the default's to the
// Newton residual tolerance (1e-8 of the force terms, here 1e-6 of each peak with room for
// the amplification over 2.5 transits), with about one correction per pass instead of two.
// The default, 'auto', is 'residual' here (no friction, no links: every pass is linear).
TEST(ContactImpact, ResidualConvergenceSavesTheConfirmingSolveAtTheSameAnswer) {
  const double L = 0.1, dt = 2e-7, T = 2 * L / kCp;
  std::map<std::string, RunResult> runs;
  for (const char* convergence : {"residual and increment", "residual", "auto"}) {
    std::string tag = convergence;
    for (char& ch : tag)
      if (ch == ' ') ch = '_';
    const std::string dir = scratchDir("convergence_" + tag);
    const std::string mesh = writeScene(dir, L, 20, 1, L, 20, 1, 1e-5, Tpetra::getDefaultComm());
    const std::string newton = std::string("<ParameterList name=\"Newton\"><Parameter name=\"Convergence\" "
                                           "type=\"string\" value=\"") + convergence + "\"/></ParameterList>";
    runs[convergence] = runDeck(dir, deck(mesh, "CL_POU2", transient("b", "Lagrange", "modified average acceleration", -0.3, dt,
                                                                    1e-5 + 2.5 * T, newton)), "b");
  }
  const RunResult& both = runs["residual and increment"];
  const RunResult& residual = runs["residual"];
  ASSERT_EQ(both.figures.steps, residual.figures.steps);
  EXPECT_EQ(both.figures.activeSetIterations, residual.figures.activeSetIterations);
  std::printf("corrections: %d (residual and increment), %d (residual); %d active-set passes\n",
              both.figures.newtonIterations, residual.figures.newtonIterations,
              residual.figures.activeSetIterations);
  // The default confirms each correction with a second solve, except where the first one is
  // exactly zero (free flight, where the predictor is exact): well over 1.5 per pass.
  EXPECT_GE(2 * both.figures.newtonIterations, 3 * residual.figures.newtonIterations);
  // One correction per pass, except where the predictor is exact (its residual at round-off,
  // no constraint violated): the rigid approach over the gap 1e-5 at 1 m/s, 50 steps of dt,
  // and the first pass of the step contact begins in (free flight until its status update).
  const int approach = int(std::floor(1e-5 / 1.0 / dt + 1e-9));
  const int saved = residual.figures.activeSetIterations - residual.figures.newtonIterations;
  EXPECT_GE(saved, approach);
  EXPECT_LE(saved, approach + 1);
  const RunResult& automatic = runs["auto"];
  EXPECT_EQ(automatic.figures.newtonIterations, residual.figures.newtonIterations);
  for (const std::string column : {"N1:DZ", "N1:VZ", "ifc:force"})
    EXPECT_EQ(automatic.h.column(column), residual.h.column(column)) << column;
  for (const std::string column : {"N1:DZ", "N1:VZ", "ifc:force"}) {
    const auto a = both.h.column(column), b = residual.h.column(column);
    ASSERT_EQ(a.size(), b.size());
    double peak = 0, diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      peak = std::max(peak, std::abs(a[i]));
      diff = std::max(diff, std::abs(a[i] - b[i]));
    }
    EXPECT_LE(diff, 1e-6 * peak) << column;
  }
}

}  // namespace
}  // namespace choc
