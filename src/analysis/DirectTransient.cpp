#include "analysis/DirectTransient.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "analysis/DirectStepView.hpp"
#include "contact/ContactNormalDirections.hpp"
#include "contact/ContactReport.hpp"
#include "contact/ContactStrategies.hpp"
#include "core/Errors.hpp"
#include "timeint/TimeGrid.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "fem/Components.hpp"
#include "fem/MatrixOps.hpp"
#include "fem/NodalBlocks.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Vector3.hpp"
#include "output/InteractionList.hpp"
#include "physics/CriticalStep.hpp"
#include "analysis/DeformedStability.hpp"
#include "physics/FiniteStrainForce.hpp"
#include "physics/LinearElasticForce.hpp"
#include "physics/LoadAssembly.hpp"
#include "solvers/FactorizationBackend.hpp"
#include "solvers/SolverChoice.hpp"
#include "physics/RigidBodies.hpp"
#include "timeint/CentralDifferenceStepper.hpp"
#include "timeint/NewmarkStepper.hpp"

namespace choc {

namespace {

// 'Contact/Status Update' as Newton's setting.
StatusTiming statusTimingOf(const std::string& update) {
  return update == "each correction"   ? StatusTiming::EachCorrection
         : update == "converged solve" ? StatusTiming::ConvergedSolve
                                       : StatusTiming::Auto;
}

}  // namespace

DirectTransient::DirectTransient(const std::string& name, const Teuchos::ParameterList& params,
                                     const std::string& inputFile)
    : Analysis(name, params, inputFile) {
  readScheme();
  readTimeSettings();
  const ParameterList& ray = params_.sublist("Rayleigh Damping");
  s_.rayleighK = ray.get<double>("Stiffness Coefficient");
  s_.rayleighM = ray.get<double>("Mass Coefficient");
  s_.contact = readContactSettings(params_, inputFile_, "Analyses/" + name_);
  s_.time.newton.maxActiveSetIterations = s_.contact.maxActiveSetIterations;
  s_.time.newton.statusTiming = statusTimingOf(s_.contact.statusUpdate);
  s_.output = readTransientOutput(params_);
  if (!s_.explicitScheme) s_.output.energy.createdNotice = 1e-3;  // the contact release term, noticed
  checkStepCount(nominalSteps(s_.time.startTime, s_.time.endTime, s_.time.timeStep), 1, s_.output.limits, inputFile_,
                 "Analyses/" + name_, s_.time.timeStep);
  const ParameterList& lp = params_.sublist("Linear Solver");
  checkContactChoice(s_.contact, {s_.explicitScheme, lp.get<std::string>("Method"), lp.get<std::string>("Preconditioner")},
                     inputFile_);
  // Central differences enforce Lagrange contact by forward increments on the lumped mass:
  // the contact nodes keep their mass ('auto' means standard there).
  if (s_.explicitScheme && s_.contact.massIsAutomatic) s_.contact.redistributeMass = false;
  {
    const ParameterList& pr = params_.sublist("Pressures");
    for (auto it = pr.begin(); it != pr.end(); ++it)
      if (pr.sublist(pr.name(it)).get<bool>("Follower") && !s_.explicitScheme && lp.get<std::string>("Method") == "CG")
        throwInput(inputFile_, path("Pressures/" + pr.name(it) + "/Follower"), "true",
                   "the load stiffness of a follower pressure is not symmetric, which CG cannot solve",
                   "use 'Linear Solver/Method' = Direct, GMRES or auto with follower pressures");
  }
}

void DirectTransient::readScheme() {
  const std::string schemeName = params_.get<std::string>("Scheme");
  s_.stability = stabilityCheckFromName(params_.get<std::string>("Stability Check"));
  s_.criticalStepInterval = params_.get<int>("Critical Step Interval");
  if (schemeName == "central differences") {
    s_.explicitScheme = true;
    return;
  }
  try {
    s_.scheme = NewmarkFamily::fromPreset(schemeName, params_.get<double>("Alpha"),
                                          params_.get<double>("Spectral Radius"),
                                          params_.get<double>("Beta"), params_.get<double>("Gamma"));
  } catch (const SchemeRangeError& e) {
    throwInput(inputFile_, path(e.parameter()), shortNumber(params_.get<double>(e.parameter())),
               std::string(e.what()) + " for scheme '" + schemeName + "'",
               "choose a value in the stable range");
  }
}

void DirectTransient::readTimeSettings() {
  TransientSettings& ts = s_.time;
  ts.timeStep = params_.get<double>("Time Step");
  ts.startTime = params_.get<double>("Start Time");
  ts.endTime = params_.get<double>("End Time");
  if (!(ts.endTime > ts.startTime))
    throwInput(inputFile_, path("End Time"), shortNumber(ts.endTime), "does not exceed the Start Time",
               "use an end time after 'Start Time' = " + shortNumber(ts.startTime));
  ts.label = "analysis '" + name_ + "'";
  if (ts.timeStep > ts.endTime - ts.startTime)
    throwInput(inputFile_, path("Time Step"), shortNumber(ts.timeStep), "longer than the run",
               "use a time step at most 'End Time' - 'Start Time' = " + shortNumber(ts.endTime - ts.startTime));
  const ParameterList& nw = params_.sublist("Newton");
  ts.newton.residualTolerance = nw.get<double>("Residual Tolerance");
  ts.newton.incrementTolerance = nw.get<double>("Increment Tolerance");
  ts.newton.maxIterations = nw.get<int>("Maximum Iterations");
  const std::string convergence = nw.get<std::string>("Convergence");
  ts.newton.convergence = convergence == "residual"                 ? Convergence::Residual
                          : convergence == "residual and increment" ? Convergence::ResidualAndIncrement
                                                                    : Convergence::Auto;
  ts.newton.adaptiveLinearTolerance = nw.get<std::string>("Linear Tolerance") == "adaptive";
  const std::string search = nw.get<std::string>("Line Search");
  ts.newton.lineSearch = search == "on" ? LineSearch::On : search == "off" ? LineSearch::Off : LineSearch::Auto;
  ts.newton.extrapolateMassless = nw.get<std::string>("Massless Start") == "extrapolated";
  ts.maxCuts = params_.sublist("Step Control").get<int>("Maximum Step Cuts");
  ts.cutFactor = params_.sublist("Step Control").get<double>("Cut Factor");
}

void DirectTransient::setup(SetupContext& ctx) {
  Model& model = ctx.model;
  b_ = std::make_unique<Built>();
  b_->K = model.stiffness();
  b_->finiteStrain = model.finiteStrain();
  b_->M = model.mass();
  b_->meshMass = b_->M;
  b_->loads = assembleLoads(model, params_, inputFile_, "Analyses/" + name_);
  buildContact(model);
  if (b_->contact && b_->contact->hasFriction()) {
    const int dimension = int(spatialComponents(model.mesh().dimension).size());
    const double kt = s_.contact.tangentialStiffness > 0 ? s_.contact.tangentialStiffness
                                                          : largestNodalDiagonal(*b_->K, model.dofs(), dimension);
    b_->contact->friction()->setTangentialStiffness(kt);
  }
  std::vector<ShockLink> links = readShockLinks(params_, model, "Analyses/" + name_);
  if (!links.empty()) b_->links = std::make_unique<DirectLinks>(std::move(links), model, model.map());
  buildSolver(model);  // an explicit run never uses it (no effective matrix is built)
  if (!s_.explicitScheme)
    refuseRigidBlocks(model, "Analyses/" + name_, "implicit ('Scheme' = '" + params_.get<std::string>("Scheme") + "')");
  if (s_.explicitScheme) setupExplicit(model);
  b_->probes = parseProbes(s_.output.history, model, path("History"), true);
  std::vector<std::string> probeColumns;
  for (const auto& p : b_->probes) probeColumns.push_back(p.column);
  std::vector<std::string> interactionColumns;
  if (b_->contact) interactionColumns = ContactReport(*b_->contact, 0).historyColumns();
  if (b_->links) {
    const std::vector<std::string> lc = b_->links->historyColumns();
    interactionColumns.insert(interactionColumns.end(), lc.begin(), lc.end());
  }
  if (b_->rigid) {  // after the links: the order of the interaction list in run()
    const std::vector<std::string> rc = b_->rigid->historyColumns();
    interactionColumns.insert(interactionColumns.end(), rc.begin(), rc.end());
  }
  b_->columns = historyColumns(probeColumns, interactionColumns, !model.firstPlasticBlock().empty(),
                               model.hasOnePointBlocks());
  const int dims = static_cast<int>(spatialComponents(model.mesh().dimension).size());
  const int contactFields = b_->contact ? static_cast<int>(ContactReport(*b_->contact, 0).nodalFieldNames().size()) : 0;
  checkOutputSize({nominalSteps(s_.time.startTime, s_.time.endTime, s_.time.timeStep), int(b_->columns.size()),
                   s_.output.exodusInterval, model.mesh().numNodes(), 3 * dims + contactFields},
                  s_.output.limits, inputFile_, "Analyses/" + name_);
  b_->checks = makeChecks(params_, model, name_);
  for (const auto& c : b_->checks) c->verify(b_->columns, s_.time.endTime);
  b_->init = buildInitialFields(params_, model, "Analyses/" + name_);
}

// The contact pairs, and the mass with the contact surfaces massless when redistributed.
// 'auto' in an implicit scheme with every block's mass lumped: the velocity update (the 3D
// Taylor quarter within 0.02 % of central differences, the bracket within 4e-5 of the
// standard-mass run, where the redistributed mass is 6.8 % and 1.7 % off:
// docs/verification/contact-mass.md); with a consistent mass, the redistributed mass.
void DirectTransient::buildContact(Model& model) {
  b_->contact = makeContactManager(s_.contact, model.mesh(), model.dofs(), model.map(), inputFile_,
                                   model.kinematics() == Kinematics::Axisymmetric);
  if (s_.contact.massIsAutomatic && s_.contact.redistributeMass && !lumpedMassDiagonal(*b_->M).is_null()) {
    s_.contact.redistributeMass = false;
    s_.contact.velocityUpdate = true;
    b_->massChoice = "the velocity update ('auto' with every block's mass lumped)";
  }
  if (s_.contact.normalMass) return buildNormalMass(model);
  if (!s_.contact.redistributeMass) return;
  const std::vector<char> massless = contactSurfaceNodes(*b_->contact, model.mesh());
  for (char c : massless) b_->masslessNodes += c;
  try {
    b_->M = model.mass(massless);
  } catch (const std::invalid_argument& e) {
    if (!s_.contact.massIsAutomatic) throwInput(inputFile_, path("Contact Mass"), "redistributed", e.what());
    b_->masslessNodes = 0;
    b_->massFallback = e.what();
    return;
  }
  if (s_.contact.massIsAutomatic)
    b_->massChoice = "redistributed ('auto' with a consistent mass): the contact faces have no inertia along the "
                     "surface; where they flow or slide along it, 'Mass' = 'lumped' (then the velocity update) or "
                     "'Contact Mass' = 'velocity update' (the implicit 3D Taylor quarter's radius: +6.5 % "
                     "redistributed, +0.3 % velocity update: docs/verification/contact-mass.md)";
}

// 'Contact Mass' = normal: the contact nodes massless along their normals, and the rotation
// onto those directions (physics/MasslessBasis.hpp).
void DirectTransient::buildNormalMass(const Model& model) {
  const std::vector<std::vector<Point3>> directions = contactNormalDirections(*b_->contact, model.mesh(), model.dofs());
  try {
    b_->M = model.mass(directions);
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile_, path("Contact Mass"), "normal", e.what());
  }
  for (const auto& d : directions) b_->masslessNodes += !d.empty();
  b_->massless = masslessBasis(directions, model.dofs(), model.map());
}

// Central differences: the lumped mass's inverse and the critical step, refused or sub-stepped.
void DirectTransient::setupExplicit(const Model& model) {
  // The element bound holds for the mesh's own lumped mass (not for a redistributed one).
  const double meshBound = b_->masslessNodes == 0 ? model.eigenvalueBound()
                                                  : std::numeric_limits<double>::infinity();
  b_->explicitPlan = std::make_unique<ExplicitPlan>(planExplicit(
      {*b_->K, *b_->M, b_->strategy.get(), b_->links.get(), meshBound, s_.rayleighK, s_.rayleighM,
       s_.time.timeStep, s_.time.endTime - s_.time.startTime, s_.stability, s_.output.limits, inputFile_, "Analyses/" + name_}));
  if (!hasRigidBodies(model)) return;
  // Rigid blocks: their nodes' inverse mass 0 (the bodies move them), and their inertia the
  // bodies' own (the kinetic energy's diagonal without their rows).
  auto* increments = dynamic_cast<ForwardIncrementStrategy*>(b_->strategy.get());
  if (increments && b_->contact->hasFriction())
    throwInput(inputFile_, path("Contact/Method"), s_.contact.methodName(),
               "friction beside rigid blocks is not available in central differences so far (issue 74)",
               "make the pairs frictionless ('Friction Coefficient' = 0)");
  b_->rigid = std::make_shared<RigidBodies>(model, *b_->explicitPlan->massDiagonal);
  b_->rigid->setGravity(parseVector3(params_.get<std::string>("Gravity"), inputFile_, path("Gravity")));
  if (increments) increments->moveWithBodies(b_->rigid.get());
  b_->rigid->zeroRows(*b_->explicitPlan->inverseMass);
  auto withoutRigid = rcp(new Vector(*b_->explicitPlan->massDiagonal, Teuchos::Copy));
  b_->rigid->zeroRows(*withoutRigid);
  b_->nodalMass = withoutRigid;
}

void DirectTransient::buildSolver(const Model& model) {
  Teuchos::ParameterList lp = params_.sublist("Linear Solver");
  const bool hasFollowers = b_->loads && !b_->loads->followers().empty();
  if (lp.get<std::string>("Method") == "auto" && !s_.explicitScheme) {
    SolverRegime r;
    r.unknowns = (long long)b_->K->getGlobalNumRows();
    if (mumpsAvailable()) r.distributedDirect = "MUMPS";
    if (b_->contact && b_->contact->method().hasMultipliers() && !s_.contact.condensable())
      r.notSymmetricBecause = "contact method '" + s_.contact.methodName() + "' has multipliers";
    else if (b_->contact && b_->contact->hasFriction())
      r.notSymmetricBecause = "contact friction";
    else if (b_->links)
      r.notSymmetricBecause = "shock links";
    else if (hasFollowers)
      r.notSymmetricBecause = "follower pressures (their load stiffness)";
    // Friction with the multipliers condensed (obstacles alone) or projected (Lagrange): W plus
    // the sliding nodes' rows.
    r.nearlySymmetric = !b_->links && b_->contact && b_->contact->hasFriction() && s_.contact.condensable();
    r.tangentChanges = b_->finiteStrain;
    if (r.unknowns > r.alwaysDirectUpTo() && (r.symmetricPositive() || r.nearlySymmetric)) {
      const EffectiveCoefficients c = s_.scheme.effectiveCoefficients(s_.time.timeStep);
      // W = ca M + cv C + cd K with C = aK K + aM M: the stiffness and mass parts of W. Measured
      // on the mesh's own mass: a redistributed contact mass leaves the contact surface's nodes
      // massless (theta infinite) but moves their mass onto the next layer, which keeps W's
      // conditioning that of the mesh's mass (the compact block at 89,373 unknowns: 26 CG +
      // Jacobi iterations per solve, docs/performance/direct-packages.md).
      r.stiffnessToMass = stiffnessToMassRatio(*b_->K, *b_->meshMass, c.ca + c.cv * s_.rayleighM,
                                               c.cd + c.cv * s_.rayleighK);
    }
    const SolverChoice choice = chooseLinearSolver(r);
    lp.set("Method", choice.method);
    if (!choice.preconditioner.empty()) lp.set("Preconditioner", choice.preconditioner);
    if (!choice.package.empty()) lp.set("Direct Package", choice.package);
    b_->solverChoice = "'auto': " + choice.reason;
  }
  // K, M and the contact rows of Lagrange and penalty contact are symmetric; friction's, the
  // links' and the follower pressures' tangents and the continuous method's pressure rows are not.
  const bool symmetric = !(b_->contact && (b_->contact->hasFriction() || s_.contact.hasPressureUnknowns())) &&
                         !b_->links && !hasFollowers;
  std::shared_ptr<const NodalBlocks> blocks;
  // (An explicit run builds the solver without using it; multiplier rows were refused with the input.)
  if (lp.get<std::string>("Preconditioner") == "Multigrid" && lp.get<std::string>("Method") != "Direct")
    blocks = std::make_shared<const NodalBlocks>(nodalBlocks(model.dofs(), model.mesh().coords));
  if (lp.get<std::string>("Method") == "Direct") b_->massPackage = lp.get<std::string>("Direct Package");
  try {
    b_->solver = makeLinearSolver(lp, symmetric, std::move(blocks));
  } catch (const InputError& e) {
    throwInput(inputFile_, path("Linear Solver"), "", e.what());
  }
  if (b_->contact)
    b_->strategy = makeContactStrategy(s_.contact, *b_->contact,
                                       {s_.explicitScheme, lp.get<std::string>("Method"), lp.get<std::string>("Preconditioner")});
}

// The stepper of the scheme: Newmark family (Newton) or central differences (explicit).
std::unique_ptr<StructuralStepper> DirectTransient::stepper(StructuralOperator& op) const {
  if (s_.explicitScheme) {
    op.storeStiffnessSymmetrically();  // one product with K per sub-step is the run's cost
    op.useDiagonalMass(b_->rigid ? b_->nodalMass : b_->explicitPlan->massDiagonal);
    auto cd = std::make_unique<CentralDifferenceStepper>(op, b_->explicitPlan->inverseMass, s_.time,
                                                         b_->explicitPlan->substeps);
    cd->moveRigidBodies(b_->rigid.get());
    cd->checkValidityEvery(s_.criticalStepInterval);
    if (b_->finiteStrain) {
      auto monitor = std::make_shared<DeformedStability>(op, *b_->explicitPlan, s_.rayleighK, s_.rayleighM,
                                                         s_.time.timeStep, s_.stability, s_.time.label);
      cd->monitorStability(s_.criticalStepInterval,
                           [monitor](const Vector& u, double t, long long n) { return (*monitor)(u, t, n); });
    }
    return cd;
  }
  op.tangentMatrix();
  auto newmark = std::make_unique<NewmarkStepper>(op, s_.scheme, s_.time);
  // The redistributed contact mass's massless DOFs start Newton from their last increments
  // extrapolated (with 'normal' they are rotated DOFs: those keep the predictor).
  if (s_.time.newton.extrapolateMassless && op.mass().masslessDofs() > 0 && op.mass().masslessRotation().is_null())
    newmark->extrapolateMassless(op.mass().masslessMask());
  return newmark;
}

// The model's internal force: element by element when some block is finite-strain, else K u.
std::shared_ptr<InternalForce> DirectTransient::internalForce(Model& model) const {
  if (model.finiteStrain()) {
    auto f = std::make_shared<FiniteStrainForce>(model);
    if (b_->loads)
      for (const auto& p : b_->loads->followers()) f->addStateLoad(p);
    return f;
  }
  return std::make_shared<LinearElasticForce>(b_->K);
}

void DirectTransient::run(RunContext& ctx) {
  const auto wallStart = std::chrono::steady_clock::now();
  auto timer = rcp(new Teuchos::StackedTimer(("Transient '" + name_ + "'").c_str()));
  StructuralOperator op(internalForce(ctx.model), b_->M, s_.rayleighK, s_.rayleighM, b_->loads, b_->strategy.get(),
                        b_->links.get(), std::move(b_->solver), timer.get());
  configure(op, ctx.model);
  TransientReport report(facts(), op, b_->contact.get(), b_->links.get());
  report.describe(ctx.model, *b_->M);
  const StateArchive* resume = resumeFor(ctx);
  ObserverSet outputs;
  std::unique_ptr<ContactReport> contactReport;
  if (b_->contact) contactReport = std::make_unique<ContactReport>(*b_->contact, ctx.model.mesh().numNodes());
  const InteractionList interactions({contactReport.get(), b_->links.get(), b_->rigid.get()});
  DirectStepView view(op, contactReport.get(), interactions.simplest(), b_->probes, outputs, timer.get());
  std::unique_ptr<StructuralStepper> scheme = stepper(op);
  scheme->addObserver(&view);
  scheme->setInitialState(*b_->init.displacement, *b_->init.velocity);
  StepLoop loop(*scheme, TimeGrid(s_.time.startTime, s_.time.endTime, s_.time.timeStep));
  const StateVectors vectors(ctx.model.dofs());
  OutputPlan plan{"transient '" + name_ + "'", ctx.outputDir + "/" + name_, b_->columns,
                  s_.time.startTime, s_.time.endTime, 1, checkpointPlan(ctx), resume};
  plan.checkpoint.archiveRun = [&](StateArchive& a) {
    loop.archive(a, vectors);
    view.archive(a, vectors);
  };
  const HistoryObserver& history = addTransientObservers(outputs, s_.output, plan, ctx.model);
  if (resume) continueView(view, *resume, vectors, ctx.model);
  const StateArchive none;
  const StepLoop::Resume from{resume ? *resume : none, vectors};
  TransientSummary sum;
  try {
    outputs.run(view, [&] { sum = loop.run(resume ? &from : nullptr); });
  } catch (...) {  // the summary of a run that stopped holds what it did up to its last accepted state
    report.record(loop.progress(), *timer, wallStart);
    figures_ = report.figures();
    report.summarizeCounts(ctx.summary, loop.progress(), loop.time());
    history.summarize(ctx.summary);
    throw;
  }
  timer->stopBaseTimer();
  reportRun(ctx, sum, report, *timer, wallStart, history);
}

// The domain of the operator's assembled small-strain blocks (checked with the elements' validity),
// and a normal contact mass's massless directions.
void DirectTransient::configure(StructuralOperator& op, Model& model) const {
  auto domain = std::make_shared<SmallStrainDomain>(model);
  if (!domain->empty()) op.setSmallStrainDomain(domain);
  if (!b_->massless.rotation.is_null()) op.inertia().useMasslessBasis(b_->massless);
  if (!b_->massPackage.empty()) op.inertia().solveMassBy(b_->massPackage);
  if (b_->rigid) op.inertia().setRigidBodies(b_->rigid);
}

// The view's records of a checkpoint's state, before the loop continues from it.
void DirectTransient::continueView(DirectStepView& view, const StateArchive& resume, const StateVectors& vectors,
                                   const Model& model) {
  view.restore(resume, vectors, model.map());
  log() << format("  continuing from the checkpoint at t = %.6e s (step %lld)\n", resume.getDouble("point/time"),
                  resume.getInt("point/nominal"));
}

// The figures of the run: recorded, logged, summarised (<name>.summary.json); then the checks.
void DirectTransient::reportRun(RunContext& ctx, const TransientSummary& sum, TransientReport& report,
                                Teuchos::StackedTimer& timer, std::chrono::steady_clock::time_point start,
                                const HistoryObserver& history) {
  report.record(sum, timer, start);
  figures_ = report.figures();
  report.logFigures(sum, ctx.model, timer);
  report.summarize(ctx.summary, sum, *ctx.model.comm());
  history.summarize(ctx.summary);
  evaluateChecks(b_->checks, history.history(), ctx.checks);
  if (history.balance().failed()) ctx.checks.push_back(history.balance().checkResult(name_));
  if (history.hourglass().failed()) ctx.checks.push_back(history.hourglass().checkResult(name_));
}

// What the report says of the run.
TransientFacts DirectTransient::facts() const {
  TransientFacts f;
  f.explicitScheme = s_.explicitScheme;
  f.schemeName = s_.scheme.name();
  f.schemeDescription = s_.scheme.describe();
  f.timeStep = s_.time.timeStep, f.startTime = s_.time.startTime, f.endTime = s_.time.endTime;
  f.rayleighK = s_.rayleighK, f.rayleighM = s_.rayleighM;
  f.solverChoice = b_->solverChoice;
  if (const ExplicitPlan* plan = b_->explicitPlan.get()) {
    f.substeps = plan->substeps, f.criticalStep = plan->criticalStep, f.bound = plan->bound;
    f.stabilityWarning = plan->stabilityWarning;
  }
  f.contactMethod = s_.contact.methodName();
  f.givenTangentialStiffness = s_.contact.tangentialStiffness > 0;
  f.masslessNodes = b_->masslessNodes;
  f.massFallback = b_->massFallback;
  f.massChoice = b_->massChoice;
  return f;
}

}  // namespace choc
