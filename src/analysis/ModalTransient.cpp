#include "analysis/ModalTransient.hpp"

#include <chrono>
#include <cmath>
#include <sstream>

#include "core/DidYouMean.hpp"
#include "core/Errors.hpp"
#include "physics/RigidBodies.hpp"
#include "fem/Components.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "fem/FieldGather.hpp"
#include "input/ParameterSpec.hpp"
#include "input/XmlInput.hpp"
#include "physics/ModalProjection.hpp"
#include "physics/StaticCorrection.hpp"
#include "restart/StateVectors.hpp"
#include "timeint/ModalStepper.hpp"
#include "timeint/TimeGrid.hpp"

namespace choc {

Teuchos::ParameterList ModalTransient::parameters() {
  Teuchos::ParameterList p;
  declareRequiredChoice(p, "Type", {"Modal Transient"}, "analysis type");
  declareRequiredString(p, "Modal Basis", "name of a Modal analysis earlier in the input");
  declareDouble(p, "Modal Damping", 0.0, "reduced damping xi of every flexible mode",
                {0.0, 1.0, false, true});
  declareString(p, "Modal Damping List", "",
                "one xi per mode (overrides 'Modal Damping'); rigid-body modes stay undamped");
  declareDouble(p, "Rigid Body Frequency", 1.0,
                "modes below this frequency [Hz] are rigid-body modes (undamped)",
                Range::nonNegative());
  declareDouble(p, "Start Time", 0.0, "initial time [s]", Range::nonNegative());
  declareRequiredDouble(p, "End Time", "final time [s]", Range::positive());
  declareRequiredDouble(p, "Time Step", "time step dt [s]", Range::positive());
  declareChoice(p, "Scheme", "symplectic Euler", modalSchemeNames(),
                "explicit scheme: the reference deck's symplectic Euler, central differences, "
                "or central differences refined near shocks (adaptive)");
  declareInt(p, "Refinement Factor", 10, "sub-steps per step near a shock (adaptive scheme)",
             Range::atLeast(1));
  declareStabilityCheck(p);
  declareBool(p, "Static Correction", false,
              "enrich the basis with the static responses to unit forces at the links' nodes "
              "along their normal directions (M- and K-orthogonalised; the log says how many)");
  declareChoice(p, "Projection", "mass-weighted", {"mass-weighted", "least-squares"},
                "projection of the initial fields on the basis");
  declareInitialConditions(p);
  declareTransientOutput(p);
  declareShockLinks(p);
  declareChecks(p);
  return p;
}

namespace {

std::vector<double> parseDampingList(const std::string& text, const std::string& file,
                                     const std::string& param) {
  std::vector<double> v;
  std::istringstream in(text);
  std::string tok;
  while (in >> tok) {
    double x = 0;
    if (!parseDecimal(tok, x) || !(x >= 0 && x < 1)) throwInput(file, param, tok, "not a damping ratio in [0, 1)");
    v.push_back(x);
  }
  return v;
}

}  // namespace

ModalTransient::ModalTransient(const std::string& name, const Teuchos::ParameterList& params,
                               const std::string& inputFile)
    : Analysis(name, params, inputFile) {
  s_.basis = params_.get<std::string>("Modal Basis");
  s_.damping = params_.get<double>("Modal Damping");
  s_.dampingList = parseDampingList(params_.get<std::string>("Modal Damping List"), inputFile_,
                                    path("Modal Damping List"));
  s_.rigidFrequency = params_.get<double>("Rigid Body Frequency");
  s_.projection = params_.get<std::string>("Projection");
  s_.staticCorrection = params_.get<bool>("Static Correction");
  if (s_.staticCorrection && !s_.dampingList.empty())
    throwInput(inputFile_, path("Modal Damping List"), params_.get<std::string>("Modal Damping List"),
               "cannot be combined with 'Static Correction' (the enriched basis has more modes, mixed "
               "by its Rayleigh-Ritz step)",
               "give one 'Modal Damping' for every mode");
  s_.stability = stabilityCheckFromName(params_.get<std::string>("Stability Check"));
  s_.scheme = parseModalScheme(params_.get<std::string>("Scheme"));
  s_.refinement = params_.get<int>("Refinement Factor");
  s_.output = readTransientOutput(params_);
  readTimeGrid();
}

void ModalTransient::readTimeGrid() {
  s_.startTime = params_.get<double>("Start Time");
  s_.endTime = params_.get<double>("End Time");
  s_.dt = params_.get<double>("Time Step");
  if (!(s_.endTime > s_.startTime))
    throwInput(inputFile_, path("End Time"), format("%.6g", s_.endTime), "must exceed the Start Time");
  // The time grid of every transient (timeint/TimeGrid.hpp).
  checkStepCount((s_.endTime - s_.startTime) / s_.dt, 1, s_.output.limits, inputFile_, "Analyses/" + name_, s_.dt);
  s_.steps = TimeGrid(s_.startTime, s_.endTime, s_.dt).steps();
}

void ModalTransient::setup(SetupContext& ctx) {
  refuseRigidBlocks(ctx.model, "Analyses/" + name_, "a modal transient");
  if (const std::string plastic = ctx.model.firstPlasticBlock(); !plastic.empty())
    throwInput(inputFile_, "Model/Blocks/" + plastic, "",
               "a modal transient ('" + name_ + "') superposes the modes of the linear model; block '" + plastic +
                   "' is plastic",
               "use a direct 'Transient' analysis for plasticity, or a 'linear elastic' material");
  if (ctx.model.finiteStrain())
    throwInput(inputFile_, "Model/Blocks/" + ctx.model.firstFiniteStrainBlock() + "/Strain", "finite",
               "a modal transient ('" + name_ + "') superposes the modes of the linear model",
               "use a direct 'Transient' analysis for finite strain, or 'Strain' = 'small'");
  const auto basis = ctx.modalAnalyses.find(s_.basis);
  if (basis == ctx.modalAnalyses.end()) {
    std::vector<std::string> names;
    for (const auto& m : ctx.modalAnalyses) names.push_back(m.first);
    throwInput(inputFile_, path("Modal Basis"), s_.basis, "no modal basis of that name has been computed",
               didYouMean(s_.basis, names) + "name a Modal analysis listed before this one in "
               "Analyses (listed before: " + joinNames(names) + ")");
  }
  if (!s_.dampingList.empty() && int(s_.dampingList.size()) != basis->second)
    throwInput(inputFile_, path("Modal Damping List"), params_.get<std::string>("Modal Damping List"),
               "has " + std::to_string(s_.dampingList.size()) + " values for " +
                   std::to_string(basis->second) + " modes");
  b_ = std::make_unique<Built>();
  b_->links = readShockLinks(params_, ctx.model, "Analyses/" + name_);
  b_->probes = parseProbes(s_.output.history, ctx.model, path("History"));
  std::vector<std::string> probeColumns;
  for (const auto& p : b_->probes) probeColumns.push_back(p.column);
  b_->columns = historyColumns(probeColumns, shockLinkColumns(b_->links));
  const int fields = 3 * static_cast<int>(spatialComponents(ctx.model.mesh().dimension).size());
  checkOutputSize({double(s_.steps), int(b_->columns.size()), s_.output.exodusInterval,
                   ctx.model.mesh().numNodes(), fields},
                  s_.output.limits, inputFile_, "Analyses/" + name_);
  b_->checks = makeChecks(params_, ctx.model, name_);
  for (const auto& c : b_->checks) c->verify(b_->columns, s_.endTime);
  b_->init = buildInitialFields(params_, ctx.model, "Analyses/" + name_);
}

// The basis named, or that basis enriched with the links' static modes.
const ModalBasis& ModalTransient::basisFor(RunContext& ctx) {
  basis_ = ctx.bases.at(s_.basis);
  if (!s_.staticCorrection) return *basis_;
  std::vector<StaticLoad> loads;
  for (const ShockLink& l : b_->links) {
    std::vector<Vec3> dirs;
    switch (l.law.shape) {
      case ObstacleShape::BiPlanY:
      case ObstacleShape::PlanY: dirs = {l.law.frame.e2}; break;
      case ObstacleShape::BiPlanZ:
      case ObstacleShape::PlanZ: dirs = {l.law.frame.e3}; break;
      default: dirs = {l.law.frame.e2, l.law.frame.e3}; break;
    }
    for (int node : {l.node1, l.node2})
      if (node >= 0)
        for (const Vec3& d : dirs) loads.push_back({node, d});
  }
  const StaticCorrection sc = enrichWithStaticModes(*basis_, ctx.model, loads, s_.rigidFrequency);
  log() << format("  static correction: %d static mode(s) added to the %zu modes of '%s' (%d already in "
                  "their span); the enriched basis reaches %.1f Hz\n",
                  sc.added, basis_->eigenvalues.size(), s_.basis.c_str(), sc.dropped,
                  sc.basis->frequencyHz(int(sc.basis->eigenvalues.size()) - 1));
  basis_ = sc.basis;
  return *basis_;
}

void ModalTransient::run(RunContext& ctx) {
  const ModalBasis& basis = basisFor(ctx);
  const Generalized g = generalizedSystem(basis);
  double residuals[2];
  ModalState state = initialState(ctx.model, basis, residuals);
  ModalLinks links(b_->links, ctx.model, basis);
  describe(ctx.model, basis, g, links, residuals);
  const int substeps = stepsPerStep(g, links);
  ModalIntegrator integrator(s_.scheme, g.omega2, g.damping, links, s_.refinement);
  std::vector<long long> probeDofs;
  for (const auto& p : b_->probes) probeDofs.push_back(p.dof);
  ModalStepView view(state, integrator, links, basis, g.omega2,
                     {b_->probes, gatherRows(*basis.vectors, probeDofs)},
                     s_.scheme == ModalScheme::SymplecticEuler);
  view.setSubstep(s_.dt / substeps);
  ObserverSet outputs;
  OutputPlan plan{"modal transient '" + name_ + "'", ctx.outputDir + "/" + name_, b_->columns,
                  s_.startTime, s_.endTime, ctx.model.comm()->getSize() > 1 ? 50 : 1};
  const StateArchive* resume = resumeFor(ctx);
  plan.resume = resume;
  plan.checkpoint = checkpointPlan(ctx);
  const StateVectors vectors(ctx.model.dofs());
  const ModalCheckpoint cp{state, links, basis, *ctx.model.mass()};
  ModalStepper stepper(integrator, state, s_.startTime, substeps,
                       {[&](const StepInfo& i) {
                          view.at(i.nominal, i.dt, i.last);
                          outputs.step(view);
                        },
                        [&](double t) { outputs.substep(view, t); },
                        [&](StateArchive& a, const StateVectors& v) { archiveState(cp, a, v); },
                        [&](const StateArchive& a, const StateVectors& v) { resumeState(cp, a, v); }});
  StepLoop loop(stepper, TimeGrid(s_.startTime, s_.endTime, s_.dt));
  plan.checkpoint.archiveRun = [&](StateArchive& a) { loop.archive(a, vectors); };
  const HistoryObserver& history = addTransientObservers(outputs, s_.output, plan, ctx.model);
  integrate(loop, outputs, view, resume, vectors, integrator, ctx.summary, history);
  summarize(ctx.summary, basis, g, links, substeps, integrator.subStepsTaken());
  history.summarize(ctx.summary);
  evaluateChecks(b_->checks, history.history(), ctx.checks);
  if (history.balance().failed()) ctx.checks.push_back(history.balance().checkResult(name_));
}

void ModalTransient::summarize(RunSummary& s, const ModalBasis& basis, const Generalized& g,
                               const ModalLinks& links, int substeps, long long taken) const {
  s.set("scheme", params_.get<std::string>("Scheme"));
  s.set("modes", static_cast<long long>(basis.eigenvalues.size()));
  s.set("time_step", s_.dt);
  s.set("end_time", s_.endTime);
  s.set("steps", static_cast<long long>(s_.steps));
  s.set("time_reached", s_.endTime);
  s.set("substeps_per_step", substeps);
  s.set("substep", s_.dt / substeps);
  s.set("substeps_taken", taken);
  s.set("critical_step", explicitCriticalStep(std::sqrt(g.omega2Max + links.linkOmega2Bound()),
                                              std::max(g.xiMax, links.linkDampingRatioBound())));
  s.set("links", static_cast<long long>(b_->links.size()));
}

namespace {

// The modal vectors of the state (coordinates, velocities, accelerations, link forces and the
// rigid links' constraint force), by record name.
std::vector<std::pair<std::string, std::vector<double>*>> modalVectors(ModalState& s, std::vector<double>* cf) {
  std::vector<std::pair<std::string, std::vector<double>*>> v = {{"q", &s.q}, {"v", &s.v}, {"a", &s.a}, {"f", &s.f}};
  if (cf) v.emplace_back("constraintForce", cf);
  return v;
}

}  // namespace

// With the integrator's records (ModalStepper), the eigenvalues (which tell whether a restart
// recomputed the same basis) and every modal vector expanded on the basis (physical fields in
// node order), from which a restart on a basis computed on another number of ranks projects
// its coordinates.
void ModalTransient::archiveState(const ModalCheckpoint& c, StateArchive& a, const StateVectors& vectors) const {
  a.putVector("modal/eigenvalues", c.basis.eigenvalues);
  std::vector<double> cf = c.links.constraintForce() ? *c.links.constraintForce() : std::vector<double>();
  Vector x(c.mass.getRowMap());
  for (auto& [name, vec] : modalVectors(c.state, c.links.constraintForce() ? &cf : nullptr)) {
    expandOnBasis(*c.basis.vectors, *vec, x);
    vectors.put(a, "modal/physical/" + name, x);
  }
}

// After the integrator's records are restored (ModalStepper): on another basis, the state
// projected on this one.
void ModalTransient::resumeState(const ModalCheckpoint& c, const StateArchive& a, const StateVectors& vectors) const {
  const std::vector<double> was = a.getVector<double>("modal/eigenvalues");
  if (was == c.basis.eigenvalues) return;
  // Another basis of (nearly) the same space: q' = Phi'^T M (Phi q) for every modal vector.
  double change = 0.0, largest = 0.0;
  for (size_t k = 0; k < was.size() && k < c.basis.eigenvalues.size(); ++k) {
    change = std::max(change, std::abs(was[k] - c.basis.eigenvalues[k]));
    largest = std::max(largest, std::abs(was[k]));
  }
  change /= std::max(largest, 1e-300);
  std::vector<double> cf;
  Vector x(c.mass.getRowMap());
  for (auto& [name, vec] : modalVectors(c.state, c.links.constraintForce() ? &cf : nullptr)) {
    vectors.get(a, "modal/physical/" + name, x);
    *vec = projectOnBasis(*c.basis.vectors, c.mass, x, "mass-weighted");
  }
  if (c.links.constraintForce()) c.links.setConstraintForce(cf);
  log() << format("  the modal basis differs from the checkpoint's (eigenvalues changed by up to "
                  "%.2e of the largest): the state is projected on this one\n", change);
}

ModalTransient::Generalized ModalTransient::generalizedSystem(const ModalBasis& basis) const {
  const int nm = static_cast<int>(basis.eigenvalues.size());
  Generalized g;
  g.omega2.assign(nm, 0.0);
  g.damping.assign(nm, 0.0);
  std::vector<double> xi = s_.dampingList.empty() ? std::vector<double>(nm, s_.damping) : s_.dampingList;
  for (int k = 0; k < nm; ++k) {
    g.omega2[k] = std::max(0.0, basis.eigenvalues[k]);
    if (basis.frequencyHz(k) < s_.rigidFrequency) {
      xi[k] = 0.0;
      ++g.rigid;
    }
    g.damping[k] = 2.0 * xi[k] * std::sqrt(g.omega2[k]);
    g.omega2Max = std::max(g.omega2Max, g.omega2[k]);
    g.xiMax = std::max(g.xiMax, xi[k]);
  }
  return g;
}

// The initial fields projected on the basis; residuals[0, 1]: of the displacement, velocity.
ModalState ModalTransient::initialState(Model& m, const ModalBasis& basis,
                                        double residuals[2]) const {
  ModalState state;
  state.q = projectOnBasis(*basis.vectors, *m.mass(), *b_->init.displacement, s_.projection);
  state.v = projectOnBasis(*basis.vectors, *m.mass(), *b_->init.velocity, s_.projection);
  residuals[0] = projectionResidual(*basis.vectors, *b_->init.displacement, state.q);
  residuals[1] = projectionResidual(*basis.vectors, *b_->init.velocity, state.v);
  return state;
}

void ModalTransient::describe(const Model& model, const ModalBasis& basis, const Generalized& g,
                              const ModalLinks& links, const double residuals[2]) const {
  const int nm = static_cast<int>(basis.eigenvalues.size());
  const double dtCrit = explicitCriticalStep(std::sqrt(g.omega2Max + links.linkOmega2Bound()),
                                             std::max(g.xiMax, links.linkDampingRatioBound()));
  log() << format("  %lld unknowns; basis '%s': %d modes (%d rigid), %.1f Hz to %.1f Hz; %zu link(s)\n"
                  "  projection (%s) residual: displacement %.2e, velocity %.2e\n"
                  "  critical step %.4e s (modes + link stiffness), dt = %.4e s, %lld steps\n",
                  model.dofs().numGlobal(), s_.basis.c_str(), nm, g.rigid, basis.frequencyHz(0),
                  basis.frequencyHz(nm - 1), links.links().size(), s_.projection.c_str(),
                  residuals[0], residuals[1], dtCrit, s_.dt, s_.steps);
}

// Sub-steps per step from the stability policy (timeint/StabilityPolicy.hpp); penalty links
// switch on and off.
int ModalTransient::stepsPerStep(const Generalized& g, const ModalLinks& links) const {
  const double dtCrit = explicitCriticalStep(std::sqrt(g.omega2Max + links.linkOmega2Bound()),
                                             std::max(g.xiMax, links.linkDampingRatioBound()));
  bool penalty = false;
  for (const auto& l : links.links()) penalty = penalty || !l.law.rigid;
  const StabilityDecision d = decideStability(s_.dt, dtCrit, penalty ? Switching::PenaltyLinks : Switching::None, s_.stability);
  if (d.refused)
    throwInput(inputFile_, path("Time Step"), format("%.6g", s_.dt), d.reason + "; the highest frequency is that of the modes with the link stiffness",
               "use a time step at most " + shortNumber(d.stableStep) + " s, or set 'Stability Check' to 'substep'");
  if (d.warned) log() << "  warning: " << d.reason << "\n";
  if (d.substeps == 1) return 1;
  checkStepCount(double(s_.steps), d.substeps, s_.output.limits, inputFile_, "Analyses/" + name_, s_.dt);
  log() << "  " << d.reason << ": " << d.substeps << " sub-steps per step\n";
  return d.substeps;
}

void ModalTransient::integrate(StepLoop& loop, ObserverSet& outputs, TransientView& view,
                               const StateArchive* resume, const StateVectors& vectors,
                               const ModalIntegrator& integrator, RunSummary& stopped,
                               const HistoryObserver& history) const {
  if (resume)
    log() << format("  continuing from the checkpoint at t = %.6e s (step %lld)\n",
                    resume->getDouble("driver/time"), resume->getInt("driver/nominal"));
  const auto start = std::chrono::steady_clock::now();
  const StateArchive none;
  const StepLoop::Resume from{resume ? *resume : none, vectors};
  long long first = 1;
  try {
    outputs.run(view, [&] {
      first = resume ? resume->getInt("driver/nominal") + 1 : 1;
      loop.run(resume ? &from : nullptr);
    });
  } catch (...) {
    stopped.set("steps", static_cast<long long>(loop.progress().steps));
    stopped.set("time_reached", loop.time());
    stopped.set("substeps_taken", integrator.subStepsTaken());
    history.summarize(stopped);
    throw;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const long long taken = s_.steps - first + 1;
  log() << format("  %lld steps, %lld sub-steps in %.4f s (%.2f us per step, output included)\n",
                  taken, integrator.subStepsTaken(), seconds, 1e6 * seconds / std::max(1LL, taken));
}

}  // namespace choc
