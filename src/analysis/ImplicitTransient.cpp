#include "analysis/ImplicitTransient.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_StackedTimer.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "analysis/EnergyBalance.hpp"
#include "analysis/HistoryChecks.hpp"
#include "analysis/HistoryProbes.hpp"
#include "analysis/InitialConditions.hpp"
#include "analysis/StructuralOperator.hpp"
#include "contact/ContactManager.hpp"
#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"
#include "input/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "output/ExodusResults.hpp"
#include "output/HistoryCsv.hpp"
#include "output/Interrupt.hpp"
#include "output/Log.hpp"
#include "solvers/LinearSolver.hpp"
#include "timeint/TransientDriver.hpp"

namespace choc {

Teuchos::ParameterList ImplicitTransient::parameters() {
  Teuchos::ParameterList p;
  declareRequiredChoice(p, "Type", {"Transient"}, "analysis type");
  declareChoice(p, "Scheme", "modified average acceleration", NewmarkFamily::presetNames(),
                "Newmark-family preset (see src/timeint/NewmarkFamily.hpp)");
  declareDouble(p, "Alpha", -0.1,
                "alpha of 'modified average acceleration' and 'HHT', in [-1/3, 0]: "
                "beta = (1-alpha)^2/4, gamma = 1/2 - alpha");
  declareDouble(p, "Spectral Radius", 0.8, "rho_inf of 'generalized-alpha', in [0, 1]");
  declareDouble(p, "Beta", 0.25, "beta of 'Newmark' (gamma/2 <= beta <= 1)");
  declareDouble(p, "Gamma", 0.5, "gamma of 'Newmark' (>= 1/2)");
  declareRequiredDouble(p, "Time Step", "dt [s]", Range::positive());
  declareRequiredDouble(p, "End Time", "end of the run [s]", Range::positive());
  ParameterList& ray = declareSublist(p, "Rayleigh Damping", "C = a K + b M");
  declareDouble(ray, "Stiffness Coefficient", 0.0, "a [s]", Range::nonNegative());
  declareDouble(ray, "Mass Coefficient", 0.0, "b [1/s]", Range::nonNegative());
  ParameterList& nw = declareSublist(p, "Newton", "Newton iterations of each step");
  declareDouble(nw, "Residual Tolerance", 1e-8,
                "||R|| / (largest of ||inertia||, ||forces||, ||contact forces||)", Range::positive());
  declareDouble(nw, "Increment Tolerance", 1e-8,
                "||du|| of the last correction / ||u_{n+1} - predictor||", Range::positive());
  declareInt(nw, "Maximum Iterations", 10, "Newton corrections per active-set pass", Range::atLeast(1));
  declareChoice(nw, "Convergence", "residual and increment", {"residual and increment", "residual"},
                "'residual' accepts an iterate on the residual test alone, saving the solve that "
                "confirms a small increment (about half the solves of a linear step)");
  ParameterList& sc = declareSublist(p, "Step Control", "what a failed step does");
  declareInt(sc, "Maximum Step Cuts", 0,
             "cuts of dt allowed inside one step before the run stops (0: stop at once)",
             Range::atLeast(0));
  declareDouble(sc, "Cut Factor", 0.5, "dt <- factor dt after a failure", Range{0.0, 1.0, true, true});
  p.set("Linear Solver", linearSolverParameters(), "linear solver of the Newton corrections");
  ParameterList& ct = declareSublist(p, "Contact", "unilateral contact between side sets");
  declareChoice(ct, "Method", "None", {"None", "Lagrange", "Penalty", "Continuous"},
                "Lagrange: multipliers with an active set (CONTRAINTE); Penalty: E_N per slave "
                "node (PENALISATION); Continuous: augmented Lagrangian with pressure unknowns "
                "(CONTINUE)");
  declareDouble(ct, "Penalty Stiffness", 1e10, "E_N [N/m] per slave node (Penalty)", Range::positive());
  declareDouble(ct, "Augmentation Coefficient", 1e10,
                "c [N/m] of the augmented pressure lambda - c g (Continuous)", Range::positive());
  declareDouble(ct, "Gap Tolerance", 1e-12,
                "penetration [m] above which an inactive node enters the active set "
                "(Lagrange, Continuous)",
                Range::nonNegative());
  declareInt(ct, "Maximum Active Set Iterations", 20,
             "Newton solves per step while the active set changes", Range::atLeast(1));
  ParameterList& pr = declareNamedSublists(ct, "Pairs", "contact pairs, by name");
  declareRequiredString(pr, "Master Side Set", "QUAD4 faces (HEX8 sides), outward normal");
  declareRequiredString(pr, "Slave Side Set", "faces whose nodes are the slave nodes");
  declareDouble(pr, "Search Distance", 1e-3, "largest initial |gap| of a pairing [m]", Range::positive());
  declareChoice(p, "Contact Mass", "standard", {"standard", "redistributed"},
                "standard: the blocks' mass matrices as they are; redistributed: the nodes of the "
                "contact pairs' master and slave side sets carry no mass, each element touching "
                "them has its mass moved onto its other nodes (element mass kept in every "
                "direction; Khenous, Laborde, Renard 2008). Removes the chatter of implicit "
                "schemes with exactly enforced contact (Lagrange, Continuous) at weak numerical "
                "damping, and the average-acceleration rule then keeps the energy through "
                "impacts; the contact surfaces' displacements are found statically each step");
  ParameterList& nf = declareNamedSublists(p, "Nodal Forces", "constant forces, by name");
  declareRequiredString(nf, "Node Set", "node set receiving the force");
  declareChoice(nf, "Component", "DX", {"DX", "DY", "DZ"}, "direction");
  declareRequiredDouble(nf, "Value", "force per node [N]");
  declareEnergyBalance(p);
  declareInitialConditions(p);
  declareString(p, "History", "", "recorded quantities, e.g. 'N1:DZ N1:VZ'");
  declareBool(p, "Write Exodus", true, "write <name>.exo");
  declareInt(p, "Exodus Interval", 10, "write every N-th step to Exodus (and the last)",
             Range::atLeast(1));
  declareInt(p, "Log Interval", 0, "print a progress line every N steps (0: none)", Range::atLeast(0));
  declareChecks(p);
  return p;
}

namespace {

// History and Exodus output hung on the step hook.
class TransientOutput : public StepObserver {
 public:
  TransientOutput(const Model& model, RCP<const CrsMatrix> K, RCP<const CrsMatrix> M,
                  const ContactManager* contact, std::vector<Probe> probes, HistoryCsv* csv,
                  ExodusResultsWriter* exo, int exoInterval, Teuchos::StackedTimer* timer,
                  RecordedHistory& history, int logInterval, double rayleighK, double rayleighM,
                  RCP<const Vector> load, EnergyBalanceMonitor* balance)
      : model_(model), K_(K), M_(M), contact_(contact), probes_(std::move(probes)), csv_(csv),
        exo_(exo), exoInterval_(exoInterval), timer_(timer), history_(history),
        logInterval_(logInterval), tmp_(K->getRowMap()), aK_(rayleighK), aM_(rayleighM),
        load_(load), balance_(balance) {}

  static std::vector<std::string> columns(const std::vector<Probe>& probes,
                                          const ContactManager* contact) {
    std::vector<std::string> c;
    for (const auto& p : probes) c.push_back(p.column);
    for (const char* e : {"energy:kinetic", "energy:strain", "energy:contact", "energy:dissipated",
                          "energy:total", "energy:balance"})
      c.push_back(e);
    if (contact)
      for (int p = 0; p < contact->numPairs(); ++p) {
        c.push_back(contact->pair(p).name + ":force");
        c.push_back(contact->pair(p).name + ":gap");
      }
    return c;
  }

  void stepAccepted(const StepInfo& info, const Vector& u, const Vector& v,
                    const Vector& a) override {
    TimerScope ts(timer_, "Transient: output");
    // Probes: owned values summed across ranks.
    std::vector<double> mine(probes_.size(), 0.0), vals(probes_.size(), 0.0);
    auto map = u.getMap();
    for (size_t k = 0; k < probes_.size(); ++k) {
      if (probes_[k].dof < 0) continue;
      const LO l = map->getLocalElement(GO(probes_[k].dof));
      if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
      const Vector& f = probes_[k].field == ProbeField::Displacement ? u
                        : probes_[k].field == ProbeField::Velocity   ? v
                                                                     : a;
      mine[k] = f.getData()[l];
    }
    if (!mine.empty())
      Teuchos::reduceAll<int, double>(*map->getComm(), Teuchos::REDUCE_SUM, int(mine.size()),
                                      mine.data(), vals.data());
    M_->apply(v, tmp_);
    const double kinetic = 0.5 * v.dot(tmp_);
    K_->apply(u, tmp_);
    const double strain = 0.5 * u.dot(tmp_);
    const double cenergy = contact_ ? contact_->energy(u) : 0.0;
    // Rayleigh damping power v^T C v = aK v^T K v + aM v^T M v, integrated by the trapezoidal
    // rule over the step; external work of the constant loads f.(u - u0), exact.
    double power = aM_ * 2.0 * kinetic;
    if (aK_ != 0.0) {
      K_->apply(v, tmp_);
      power += aK_ * v.dot(tmp_);
    }
    if (info.step == 0) u0_ = rcp(new Vector(u, Teuchos::Copy));
    dissipated_ += 0.5 * info.dt * (lastPower_ + power);
    lastPower_ = power;
    double external = 0.0;
    if (!load_.is_null()) {
      tmp_.update(1.0, u, -1.0, *u0_, 0.0);
      external = load_->dot(tmp_);
    }
    vals.push_back(kinetic);
    vals.push_back(strain);
    vals.push_back(cenergy);
    vals.push_back(dissipated_);
    vals.push_back(kinetic + strain + cenergy);
    vals.push_back(balance_ ? balance_->update(info.time, kinetic + strain + cenergy, dissipated_, external)
                            : 0.0);
    std::vector<double> f, g;
    if (contact_) {
      f = contact_->forces(u);
      g = contact_->gaps(u);
      for (int p = 0; p < contact_->numPairs(); ++p) {
        double force = 0.0, gap = std::numeric_limits<double>::infinity();
        for (int s = 0; s < contact_->numConstraints(); ++s)
          if (contact_->constraints()[s].geometry.pair == p) {
            force += f[s];
            gap = std::min(gap, g[s]);
          }
        vals.push_back(force);
        vals.push_back(gap);
      }
    }
    const auto cols = columns(probes_, contact_);
    for (size_t k = 0; k < vals.size(); ++k)  // never a non-finite value in an output
      if (!std::isfinite(vals[k])) {
        char what[200];
        std::snprintf(what, sizeof what, "the solution is not finite at t = %.6e s (%s = %g)",
                      info.time, cols[k].c_str(), vals[k]);
        throw NumericalError(std::string("transient: ") + what);
      }
    history_.times.push_back(info.time);
    for (size_t k = 0; k < cols.size(); ++k) history_.columns[cols[k]].push_back(vals[k]);
    if (csv_) csv_->appendRow(info.time, vals);
    if (logInterval_ > 0 && info.step % logInterval_ == 0) {
      char line[200];
      std::snprintf(line, sizeof line, "  step %6d  t = %.6e s  Newton %d  active-set passes %d%s\n",
                    info.step, info.time, info.newton.iterations, info.newton.activeSetIterations,
                    contact_ ? (", " + std::to_string(contact_->activeCount()) + " active").c_str() : "");
      log() << line;
    }
    if (exoInterval_ > 0 && (info.step % exoInterval_ == 0 || info.last)) writeExodus(info, u, v, a, f, g);
    // SIGINT/SIGTERM: stop at this step boundary (the caller renames the outputs .incomplete).
    throwIfInterrupted("transient", info.time, model_.rawComm());
  }

 private:
  void writeExodus(const StepInfo& info, const Vector& u, const Vector& v, const Vector& a,
                   const std::vector<double>& f, const std::vector<double>& g) {
    const DofMap& dofs = model_.dofs();
    const auto U = gatherAll(u, 0, dofs), V = gatherAll(v, 0, dofs), A = gatherAll(a, 0, dofs);
    if (!exo_) return;  // not rank 0
    std::vector<std::vector<double>> nodal;
    for (const auto* X : {&U, &V, &A})
      for (int c : {DX, DY, DZ}) nodal.push_back(nodalComponent(*X, dofs, c));
    std::vector<double> globals;
    const auto& h = history_.columns;
    for (const char* e : {"energy:kinetic", "energy:strain", "energy:contact", "energy:total"})
      globals.push_back(h.at(e).back());
    if (contact_) {
      const int n = model_.mesh().numNodes();
      std::vector<double> force(n, 0.0), pressure(n, 0.0), gap(n, 0.0), status(n, 0.0);
      double total = 0.0;
      for (int s = 0; s < contact_->numConstraints(); ++s) {
        const auto& geo = contact_->constraints()[s].geometry;
        force[geo.slaveNode] = f[s];
        pressure[geo.slaveNode] = geo.area > 0 ? f[s] / geo.area : 0.0;
        gap[geo.slaveNode] = g[s];
        status[geo.slaveNode] = contact_->status()[s] ? 1.0 : 0.0;
        total += f[s];
      }
      for (auto* x : {&force, &pressure, &gap, &status}) nodal.push_back(*x);
      globals.push_back(total);
      globals.push_back(contact_->activeCount());
    }
    exo_->writeStep(info.time, nodal, globals);
  }

  const Model& model_;
  RCP<const CrsMatrix> K_, M_;
  const ContactManager* contact_;
  std::vector<Probe> probes_;
  HistoryCsv* csv_;
  ExodusResultsWriter* exo_;
  int exoInterval_;
  Teuchos::StackedTimer* timer_;
  RecordedHistory& history_;
  int logInterval_;
  Vector tmp_;
  double aK_ = 0.0, aM_ = 0.0;
  RCP<const Vector> load_;
  EnergyBalanceMonitor* balance_ = nullptr;
  RCP<Vector> u0_;
  double dissipated_ = 0.0, lastPower_ = 0.0;
};

std::string fmtDouble(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

}  // namespace

void ImplicitTransient::run(RunContext& ctx) {
  const auto wallStart = std::chrono::steady_clock::now();
  Model& model = ctx.model;
  const std::string& file = inputFile_;
  auto timer = rcp(new Teuchos::StackedTimer(("Transient '" + name_ + "'").c_str()));

  // Scheme.
  const std::string schemeName = params_.get<std::string>("Scheme");
  NewmarkFamily scheme = NewmarkFamily::averageAcceleration();
  try {
    scheme = NewmarkFamily::fromPreset(schemeName, params_.get<double>("Alpha"),
                                       params_.get<double>("Spectral Radius"),
                                       params_.get<double>("Beta"), params_.get<double>("Gamma"));
  } catch (const SchemeRangeError& e) {
    throwInput(file, path(e.parameter()), fmtDouble(params_.get<double>(e.parameter())),
               std::string(e.what()) + " for scheme '" + schemeName + "'",
               "choose a value in the stable range");
  }
  TransientSettings ts;
  ts.timeStep = params_.get<double>("Time Step");
  ts.endTime = params_.get<double>("End Time");
  ts.label = "analysis '" + name_ + "'";
  if (ts.timeStep > ts.endTime)
    throwInput(file, path("Time Step"), fmtDouble(ts.timeStep), "longer than the run",
               "use a time step below 'End Time' = " + fmtDouble(ts.endTime));
  const ParameterList& nw = params_.sublist("Newton");
  ts.newton.residualTolerance = nw.get<double>("Residual Tolerance");
  ts.newton.incrementTolerance = nw.get<double>("Increment Tolerance");
  ts.newton.maxIterations = nw.get<int>("Maximum Iterations");
  ts.newton.requireIncrement = nw.get<std::string>("Convergence") != "residual";
  ts.maxCuts = params_.sublist("Step Control").get<int>("Maximum Step Cuts");
  ts.cutFactor = params_.sublist("Step Control").get<double>("Cut Factor");

  auto K = model.stiffness();
  auto M = model.mass();
  const double aK = params_.sublist("Rayleigh Damping").get<double>("Stiffness Coefficient");
  const double aM = params_.sublist("Rayleigh Damping").get<double>("Mass Coefficient");

  // Constant nodal forces.
  RCP<Vector> load;
  const ParameterList& nf = params_.sublist("Nodal Forces");
  if (nf.numParams() > 0) {
    load = rcp(new Vector(model.map()));
    for (auto it = nf.begin(); it != nf.end(); ++it) {
      const ParameterList& f = nf.sublist(nf.name(it));
      const std::string pp = path("Nodal Forces/" + nf.name(it));
      const NodeSet& ns = model.nodeSet(f.get<std::string>("Node Set"), pp + "/Node Set");
      const int comp = componentFromName(f.get<std::string>("Component"));
      for (int n : ns.nodes) {
        const long long d = model.dof(n, comp);
        if (d >= 0 && model.dofs().ownsNode(n)) load->sumIntoGlobalValue(GO(d), f.get<double>("Value"));
      }
    }
  }

  // Contact.
  const ParameterList& ct = params_.sublist("Contact");
  const std::string method = ct.get<std::string>("Method");
  std::unique_ptr<ContactManager> contact;
  ts.newton.maxActiveSetIterations = ct.get<int>("Maximum Active Set Iterations");
  if (method != "None") {
    const ParameterList& pairs = ct.sublist("Pairs");
    if (pairs.numParams() == 0)
      throwInput(file, path("Contact/Pairs"), "", "contact method '" + method + "' needs a pair",
                 "add a sublist with 'Master Side Set' and 'Slave Side Set'");
    std::vector<PairDefinition> defs;
    for (auto it = pairs.begin(); it != pairs.end(); ++it) {
      const ParameterList& pl = pairs.sublist(pairs.name(it));
      defs.push_back({pairs.name(it), pl.get<std::string>("Master Side Set"),
                      pl.get<std::string>("Slave Side Set"), pl.get<double>("Search Distance")});
    }
    const double gapTol = ct.get<double>("Gap Tolerance");
    std::unique_ptr<ContactMethod> m =
        method == "Lagrange" ? makeLagrangeContact(gapTol)
        : method == "Penalty" ? makePenaltyContact(ct.get<double>("Penalty Stiffness"))
                              : makeAugmentedLagrangianContact(ct.get<double>("Augmentation Coefficient"), gapTol);
    try {
      contact = std::make_unique<ContactManager>(model.mesh(), model.dofs(), model.map(), defs, std::move(m));
    } catch (const std::invalid_argument& e) {
      throwInput(file, path("Contact/Pairs"), "", e.what(),
                 "check the side set names and 'Search Distance'");
    }
  }
  // Mass redistribution: the contact surfaces' nodes carry no mass.
  long long masslessNodes = 0;
  if (params_.get<std::string>("Contact Mass") == "redistributed") {
    if (!contact)
      throwInput(file, path("Contact Mass"), "redistributed", "there are no contact surfaces",
                 "set 'Contact/Method' and 'Contact/Pairs', or use 'standard'");
    const Mesh& mesh = model.mesh();
    std::vector<char> massless(mesh.numNodes(), 0);
    for (int p = 0; p < contact->numPairs(); ++p)
      for (const std::string& name : {contact->pair(p).masterSideSet, contact->pair(p).slaveSideSet}) {
        const SideSet* ss = mesh.findSideSet(name);  // checked by the pairing
        for (size_t k = 0; ss && k < ss->elements.size(); ++k)
          for (int n : mesh.sideNodes(ss->elements[k], ss->sides[k])) massless[n] = 1;
      }
    for (char c : massless) masslessNodes += c;
    try {
      M = model.mass(massless);
    } catch (const std::invalid_argument& e) {
      throwInput(file, path("Contact Mass"), "redistributed", e.what());
    }
  }
  const ParameterList& lsp = params_.sublist("Linear Solver");
  if (contact && contact->method().hasMultipliers() && lsp.get<std::string>("Method") == "CG")
    throwInput(file, path("Linear Solver/Method"), "CG",
               "the saddle-point system of contact method '" + method + "' is indefinite",
               "use Direct, GMRES or MINRES (or the Penalty method with CG)");
  std::unique_ptr<LinearSolver> solver;
  try {
    solver = makeLinearSolver(lsp);
  } catch (const InputError& e) {
    throwInput(file, path("Linear Solver"), "", e.what());
  }

  // History columns and checks.
  const std::vector<Probe> probes = parseProbes(params_.get<std::string>("History"), model, path("History"));
  const std::vector<std::string> cols = TransientOutput::columns(probes, contact.get());
  verifyChecks(params_, cols, ts.endTime, file, "Analyses/" + name_);
  InitialFields init = buildInitialFields(params_, model, "Analyses/" + name_);

  StructuralOperator op(K, M, aK, aM, load, contact.get(), std::move(solver), timer.get());
  log() << "  " << model.dofs().numGlobal() << " unknowns"
        << (contact && contact->method().hasMultipliers()
                ? " (+ " + std::to_string(contact->numConstraints()) + " contact pressures)"
                : std::string())
        << "; " << scheme.describe() << "\n";
  log() << "  dt = " << ts.timeStep << " s to " << ts.endTime << " s; Rayleigh C = " << aK
        << " K + " << aM << " M; linear solver " << op.solver().description() << "\n";
  if (masslessNodes > 0) {
    // 1^T M 1 over the free DOFs (the mass summed over the free directions), before and after.
    Vector one(model.map()), y(model.map());
    one.putScalar(1.0);
    model.mass()->apply(one, y);
    const double before = one.dot(y);
    M->apply(one, y);
    char line[240];
    std::snprintf(line, sizeof line,
                  "  contact mass: redistributed: %lld contact-surface nodes massless (%lld DOFs); "
                  "1^T M 1 (free DOFs, kg per direction) %.12g -> %.12g\n",
                  masslessNodes, op.masslessDofs(), before, one.dot(y));
    log() << line;
  }
  if (contact) {
    log() << "  contact: " << contact->method().name() << ", " << contact->numConstraints()
          << " slave nodes paired";
    if (contact->unpairedNodes() > 0) log() << " (" << contact->unpairedNodes() << " unpaired)";
    log() << "\n";
  }

  // Outputs (rank 0 writes files).
  const std::string base = ctx.outputDir + "/" + name_;
  std::unique_ptr<HistoryCsv> csv;
  std::unique_ptr<ExodusResultsWriter> exo;
  if (isRootRank()) {
    csv = std::make_unique<HistoryCsv>(base + ".history.csv", cols);
    if (params_.get<bool>("Write Exodus")) {
      std::vector<std::string> nodal = {"DISP_X", "DISP_Y", "DISP_Z", "VEL_X", "VEL_Y", "VEL_Z",
                                        "ACC_X",  "ACC_Y",  "ACC_Z"};
      std::vector<std::string> globals = {"KINETIC_ENERGY", "STRAIN_ENERGY", "CONTACT_ENERGY",
                                          "TOTAL_ENERGY"};
      if (contact) {
        for (const char* n : {"CONTACT_FORCE", "CONTACT_PRESSURE", "CONTACT_GAP", "CONTACT_STATUS"})
          nodal.push_back(n);
        globals.push_back("CONTACT_FORCE_TOTAL");
        globals.push_back("CONTACT_ACTIVE_NODES");
      }
      exo = std::make_unique<ExodusResultsWriter>(base + ".exo", model.mesh(), nodal, globals);
    }
  }
  const bool writeExo = params_.get<bool>("Write Exodus");
  RecordedHistory history;
  EnergyBalanceMonitor balance(params_, "transient '" + name_ + "'");
  TransientOutput output(model, K, M, contact.get(), probes, csv.get(), exo.get(),
                         writeExo ? params_.get<int>("Exodus Interval") : 0, timer.get(), history,
                         params_.get<int>("Log Interval"), aK, aM, load, &balance);
  TransientDriver driver(op, scheme, ts);
  driver.addObserver(&output);
  TransientSummary sum;
  try {
    sum = driver.run(*init.displacement, *init.velocity);
  } catch (...) {
    if (csv) csv->abandon();
    if (exo) exo->abandon();
    throw;
  }
  if (csv) csv->finish();
  if (exo) exo->finish();
  log() << balance.summary();
  timer->stopBaseTimer();

  figures_.steps = sum.steps;
  figures_.newtonIterations = sum.newtonIterations;
  figures_.refactorizations = op.factorizations();
  figures_.activeSetIterations = sum.activeSetIterations;
  figures_.maxNewtonPerStep = sum.maxNewtonPerStep;
  figures_.failedSteps = sum.failedSteps;
  figures_.unknowns = op.unknowns();
  const std::string top;  // sub-timers are looked up from the base level
  figures_.assembly = timer->accumulatedTime(top + "Transient: assembly");
  figures_.linearSolve = timer->accumulatedTime(top + "Transient: linear solve");
  figures_.contact = timer->accumulatedTime(top + "Transient: contact");
  figures_.output = timer->accumulatedTime(top + "Transient: output");
  figures_.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  {
    char line[400];
    std::snprintf(line, sizeof line,
                  "  %d steps, %d Newton iterations (%.2f per step, at most %d), %d active-set "
                  "passes, %d factorisations, %d failed attempts (smallest dt %.3e s)\n",
                  sum.steps, sum.newtonIterations, double(sum.newtonIterations) / std::max(1, sum.steps),
                  sum.maxNewtonPerStep, sum.activeSetIterations, op.factorizations(), sum.failedSteps,
                  sum.smallestStep);
    log() << line;
    if (sum.krylovIterations > 0) {
      std::snprintf(line, sizeof line,
                    "  Krylov iterations: %d (%.1f per step, %.1f per Newton solve)\n",
                    sum.krylovIterations, double(sum.krylovIterations) / std::max(1, sum.steps),
                    double(sum.krylovIterations) / std::max(1, sum.newtonIterations));
      log() << line;
    }
    std::snprintf(line, sizeof line,
                  "  time: %.3f s = assembly %.3f + linear solve %.3f + contact %.3f + output %.3f "
                  "+ other (rank 0)\n",
                  figures_.wall, figures_.assembly, figures_.linearSolve, figures_.contact, figures_.output);
    log() << line;
    std::ostringstream rep;
    Teuchos::StackedTimer::OutputOptions opt;
    opt.output_minmax = model.comm()->getSize() > 1;
    opt.output_fraction = true;
    opt.print_warnings = false;
    timer->report(rep, model.comm(), opt);
    log() << rep.str();
  }

  for (auto& c : evaluateDeclaredChecks(params_, history, name_)) ctx.checks.push_back(c);
  for (auto& c : compareWithExact(params_, history, model, name_, "Analyses/" + name_)) ctx.checks.push_back(c);
}

}  // namespace choc
