#include "analysis/DirectTransient.hpp"

#include <algorithm>
#include <limits>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "analysis/DirectStepView.hpp"
#include "contact/ContactReport.hpp"
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
#include "solvers/FactorizationBackend.hpp"
#include "solvers/SolverChoice.hpp"
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

// The Newton sublist of a Transient.
void declareNewton(ParameterList& nw) {
  declareDouble(nw, "Residual Tolerance", 1e-8,
                "||R|| / (largest of ||inertia||, ||forces||, ||contact forces||)", Range::positive());
  declareDouble(nw, "Increment Tolerance", 1e-8,
                "the iterate's error / ||u_{n+1} - predictor||: theta / (1 - theta) ||du_k|| with "
                "theta = ||du_k|| / ||du_k-1|| < 1 (the error bound from the last two corrections' "
                "contraction, which accepts a quadratically converged iterate without a correction "
                "to confirm it), else the last correction ||du_k||", Range::positive());
  declareInt(nw, "Maximum Iterations", 10, "Newton corrections per active-set pass", Range::atLeast(1));
  declareChoice(nw, "Line Search", "auto", {"auto", "on", "off"},
                "whether a correction that does not decrease the residual norm is halved (up to 6 "
                "times, Armijo's test): 'auto' on where a block is plastic (J2, Johnson-Cook: a "
                "full correction can overshoot the points' changes between elastic and plastic "
                "response), off elsewhere; 'on' for every model; 'off' every correction whole");
  declareChoice(nw, "Convergence", "auto", {"auto", "residual and increment", "residual"},
                "which tests accept an iterate: 'residual and increment' both; 'residual' the "
                "residual alone, saving the solve that only confirms a small increment; 'auto' "
                "the residual alone in the passes that are linear (no friction, no shock links: "
                "one correction per step while the contact status holds) and both otherwise");
  declareChoice(nw, "Linear Tolerance", "adaptive", {"adaptive", "fixed"},
                "how far an iterative linear solver (CG, GMRES, MINRES) takes each correction: "
                "'adaptive' until its residual is a tenth of what the residual test allows (its "
                "tolerance of the reference, or the round-off floor; never tighter than 'Linear "
                "Solver/Tolerance'; the Newton tests are unchanged); 'fixed' "
                "always to 'Linear Solver/Tolerance'. A direct solve is exact either way; GMRES "
                "on a kept factorisation ('Linear Solver/Update Budget') stops as an iterative "
                "solver does");
}

// Analyses/<transient>/Pressures/<name>: dead or follower, uniform or linear in X.
void declarePressures(ParameterList& p, const char* ramp) {
  ParameterList& pr = declareNamedSublists(p, "Pressures", "pressures on side sets, by name");
  declareRequiredString(pr, "Side Set", "faces (3D) or edges (plane strain, axisymmetric) loaded");
  declareRequiredDouble(pr, "Value",
                        "pressure [Pa], positive pushing into the body (against the outward normal); "
                        "consistent nodal forces on the reference faces, or on the current ones with Follower");
  declareString(pr, "Gradient", "0 0 0",
                "the pressure's change per metre of the reference position, \"gx gy gz\" [Pa/m]: "
                "p(X) = Value + Gradient . X at each point X of the faces (a linear pressure: "
                "hydrostatic, or an end moment with Follower)");
  declareBool(pr, "Follower", false,
              "true: the pressure acts on the current faces along their current normal (a follower "
              "load, its load stiffness in Newton's tangent; needs a block with Strain = finite); "
              "false: on the reference faces (a dead load)");
  declareDouble(pr, "Ramp Time", 0.0, ramp, Range::nonNegative());
}

}  // namespace

Teuchos::ParameterList DirectTransient::parameters() {
  Teuchos::ParameterList p;
  declareRequiredChoice(p, "Type", {"Transient"}, "analysis type");
  std::vector<std::string> schemes = NewmarkFamily::presetNames();
  schemes.push_back("central differences");
  declareChoice(p, "Scheme", "modified average acceleration", schemes,
                "Newmark-family preset (see src/timeint/NewmarkFamily.hpp), or 'central "
                "differences': explicit, lumped mass, no linear solve (src/timeint/CentralDifferenceStepper.hpp)");
  declareStabilityCheck(p);
  declareInt(p, "Critical Step Interval", 100,
             "central differences with finite-strain blocks: every this many steps the critical step "
             "is estimated again on the deformed mesh (the elements' tangent against their lumped "
             "mass: 2 to 12 internal forces' cost per estimate) and 'Stability Check' decides again "
             "(src/analysis/DeformedStability.hpp); lower it for violent compression. Every central-"
             "differences run checks the elements' validity at the same interval (an inverted element, "
             "small strain out of its domain, a penetrated obstacle: docs/user-guide/errors.md; about "
             "1.5 internal forces' cost)",
             Range::positive());
  declareDouble(p, "Alpha", -0.1,
                "alpha of 'modified average acceleration' and 'HHT', in [-1/3, 0]: "
                "beta = (1-alpha)^2/4, gamma = 1/2 - alpha");
  declareDouble(p, "Spectral Radius", 0.8, "rho_inf of 'generalized-alpha', in [0, 1]");
  declareDouble(p, "Beta", 0.25, "beta of 'Newmark' (gamma/2 <= beta <= 1)");
  declareDouble(p, "Gamma", 0.5, "gamma of 'Newmark' (>= 1/2)");
  declareRequiredDouble(p, "Time Step", "dt [s]", Range::positive());
  declareDouble(p, "Start Time", 0.0,
                "time of the initial state [s] (loads' ramps and obstacles' motions are functions of "
                "the time itself, from t = 0)", Range::nonNegative());
  declareRequiredDouble(p, "End Time", "end of the run [s]", Range::positive());
  ParameterList& ray = declareSublist(p, "Rayleigh Damping", "C = a K + b M");
  declareDouble(ray, "Stiffness Coefficient", 0.0, "a [s]", Range::nonNegative());
  declareDouble(ray, "Mass Coefficient", 0.0, "b [1/s]", Range::nonNegative());
  declareNewton(declareSublist(p, "Newton", "Newton iterations of each step"));
  ParameterList& sc = declareSublist(p, "Step Control", "what a failed step does");
  declareInt(sc, "Maximum Step Cuts", 0,
             "cuts of dt allowed inside one step before the run stops (0: stop at once)",
             Range::atLeast(0));
  declareDouble(sc, "Cut Factor", 0.5, "dt <- factor dt after a failure", Range{0.0, 1.0, true, true});
  p.set("Linear Solver", linearSolverParameters(), "linear solver of the Newton corrections");
  declareContactParameters(p);
  declareShockLinks(p);
  const char* ramp = "the load grows linearly from zero at t = 0 to its value at this time [s], then "
                     "stays constant (0: full value from t = 0)";
  ParameterList& nf = declareNamedSublists(p, "Nodal Forces", "forces on the nodes of node sets, by name");
  declareRequiredString(nf, "Node Set", "node set receiving the force");
  declareChoice(nf, "Component", "DX", {"DX", "DY", "DZ"}, "direction");
  declareRequiredDouble(nf, "Value", "force per node [N]");
  declareDouble(nf, "Ramp Time", 0.0, ramp, Range::nonNegative());
  declarePressures(p, ramp);
  declareInitialConditions(p);
  declareTransientOutput(p);
  declareChecks(p);
  return p;
}

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
  checkStepCount(nominalSteps(s_.time.startTime, s_.time.endTime, s_.time.timeStep), 1, s_.output.limits, inputFile_,
                 "Analyses/" + name_, s_.time.timeStep);
  if (s_.explicitScheme && s_.contact.hasPressureUnknowns())
    throwInput(inputFile_, path("Contact/Method"), s_.contact.methodName(),
               "has pressure unknowns, which the explicit scheme (central differences) cannot solve for",
               "use Lagrange (forward-increment multipliers) or Penalty with central differences");
  // Central differences enforce Lagrange contact by forward increments on the lumped mass:
  // the contact nodes keep their mass ('auto' means standard there).
  if (s_.explicitScheme && s_.contact.massIsAutomatic) s_.contact.redistributeMass = false;
  if (const PairDefinition* fp = s_.contact.frictionPair()) {
    const std::string key = "Contact/Pairs/" + fp->name + "/Friction Coefficient";
    if (s_.explicitScheme && !s_.contact.forwardIncrementsWhenExplicit())
      throwInput(inputFile_, path(key), shortNumber(fp->friction),
                 "central differences apply friction by forward increments of Lagrange contact, not with '" +
                     s_.contact.methodName() + "' contact",
                 "use 'Contact/Method' = Lagrange, or an implicit scheme (HHT, Newmark...)");
    if (!s_.explicitScheme && params_.sublist("Linear Solver").get<std::string>("Method") == "CG")
      throwInput(inputFile_, path(key), shortNumber(fp->friction),
                 "the tangent of a sliding node is not symmetric, which CG cannot solve",
                 "use 'Linear Solver/Method' = Direct or GMRES with friction");
  }
  {
    const ParameterList& pr = params_.sublist("Pressures");
    for (auto it = pr.begin(); it != pr.end(); ++it)
      if (pr.sublist(pr.name(it)).get<bool>("Follower") && !s_.explicitScheme &&
          params_.sublist("Linear Solver").get<std::string>("Method") == "CG")
        throwInput(inputFile_, path("Pressures/" + pr.name(it) + "/Follower"), "true",
                   "the load stiffness of a follower pressure is not symmetric, which CG cannot solve",
                   "use 'Linear Solver/Method' = Direct, GMRES or auto with follower pressures");
  }
  // (Central differences make no linear solve: their forward increments need no solver.)
  // Multipliers against rigid obstacles alone are condensed out of an iterative solve, Lagrange's
  // between meshed bodies projected out; others (Continuous') make a saddle-point system.
  const bool saddlePoint = s_.contact.hasMultipliers() && !s_.contact.condensable();
  const std::string which = "' between meshed bodies";
  if (!s_.explicitScheme && saddlePoint && params_.sublist("Linear Solver").get<std::string>("Method") == "CG")
    throwInput(inputFile_, path("Linear Solver/Method"), "CG",
               "the saddle-point system of contact method '" + s_.contact.methodName() + which + " is indefinite",
               "use Direct, GMRES or MINRES (or the Penalty method with CG)");
  const Teuchos::ParameterList& lp = params_.sublist("Linear Solver");
  if (!s_.explicitScheme && saddlePoint && lp.get<std::string>("Preconditioner") == "Multigrid" &&
      lp.get<std::string>("Method") != "Direct")
    throwInput(inputFile_, path("Linear Solver/Preconditioner"), "Multigrid",
               "the Newton matrix of contact method '" + s_.contact.methodName() + which +
                   " has multiplier rows, which multigrid for elasticity does not aggregate",
               "use the Penalty method with Multigrid, or Method = Direct or auto");
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
  b_->loads = assembleLoads(model);
  buildContact(model);
  if (b_->contact && b_->contact->hasFriction()) {
    const int dimension = int(spatialComponents(model.mesh().dimension).size());
    const double kt = s_.contact.tangentialStiffness > 0 ? s_.contact.tangentialStiffness
                                                          : largestNodalDiagonal(*b_->K, model.dofs(), dimension);
    b_->contact->setTangentialStiffness(kt);
  }
  std::vector<ShockLink> links = readShockLinks(params_, model, "Analyses/" + name_);
  if (!links.empty()) b_->links = std::make_unique<DirectLinks>(std::move(links), model, model.map());
  buildSolver(model);  // an explicit run never uses it (no effective matrix is built)
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

// Nodal forces and pressures, each a load group (null when there are none).
std::shared_ptr<const Loads> DirectTransient::assembleLoads(Model& model) const {
  auto loads = std::make_shared<Loads>();
  const ParameterList& nf = params_.sublist("Nodal Forces");
  for (auto it = nf.begin(); it != nf.end(); ++it) {
    const ParameterList& f = nf.sublist(nf.name(it));
    const NodeSet& ns = model.nodeSet(f.get<std::string>("Node Set"), path("Nodal Forces/" + nf.name(it) + "/Node Set"));
    const int comp = componentFromName(f.get<std::string>("Component"));
    auto force = rcp(new Vector(model.map()));
    for (int n : ns.nodes) {
      const long long d = model.dof(n, comp);
      if (d >= 0 && model.dofs().ownsNode(n)) force->sumIntoGlobalValue(GO(d), f.get<double>("Value"));
    }
    loads->add({nf.name(it), force, f.get<double>("Ramp Time")});
  }
  const ParameterList& pr = params_.sublist("Pressures");
  for (auto it = pr.begin(); it != pr.end(); ++it) {
    const ParameterList& q = pr.sublist(pr.name(it));
    const std::string side = q.get<std::string>("Side Set");
    std::vector<Face> faces;
    try {
      faces = facesOf(model.mesh(), side);
    } catch (const std::invalid_argument& e) {
      throwInput(inputFile_, path("Pressures/" + pr.name(it) + "/Side Set"), side, e.what());
    }
    const std::string key = path("Pressures/" + pr.name(it));
    PressureField field;
    field.value = q.get<double>("Value");
    field.gradient = parseVector3(q.get<std::string>("Gradient"), inputFile_, key + "/Gradient");
    if (q.get<bool>("Follower")) {
      loads->addFollower(followerPressure(model, pr.name(it), std::move(faces), field));
      continue;
    }
    auto force = rcp(new Vector(model.map()));
    const auto nodal = pressureForces(faces, field, model.kinematics() == Kinematics::Axisymmetric);
    for (const auto& [n, fn] : nodal) {
      if (!model.dofs().ownsNode(n)) continue;
      for (int c = 0; c < 3; ++c) {
        const long long d = model.dof(n, c);
        if (d >= 0 && fn[c] != 0.0) force->sumIntoGlobalValue(GO(d), fn[c]);
      }
    }
    loads->add({pr.name(it), force, q.get<double>("Ramp Time")});
  }
  if (loads->empty()) return nullptr;
  return loads;
}

// The follower pressure `name` (Pressures/<name>, Follower = true) on its faces: finite-strain
// blocks under every face, or an input error.
std::shared_ptr<const FollowerPressure> DirectTransient::followerPressure(Model& model, const std::string& name,
                                                                          std::vector<Face> faces,
                                                                          const PressureField& field) const {
  const std::string key = path("Pressures/" + name);
  const ParameterList& q = params_.sublist("Pressures").sublist(name);
  const std::string side = q.get<std::string>("Side Set");
  if (model.firstFiniteStrainBlock().empty())
    throwInput(inputFile_, key + "/Follower", "true",
               "a follower pressure makes the model nonlinear and needs a block with Strain = finite",
               "set Strain = finite on the loaded block, or Follower = false (a dead load on the reference faces)");
  for (int e : model.mesh().findSideSet(side)->elements) {  // facesOf found the set
    const int b = model.mesh().locateElement(e).first;
    const auto& kernel = model.finiteStrainKernels()[size_t(b)];
    if (!kernel || !kernel->finiteKinematics())
      throwInput(inputFile_, key + "/Side Set", side,
                 "has faces of block '" + model.mesh().blocks[size_t(b)].name +
                     "', whose Strain is small: a follower pressure loads finite-strain blocks",
                 "set Strain = finite on that block, or Follower = false");
  }
  const int components = static_cast<int>(spatialComponents(model.mesh().dimension).size());
  return std::make_shared<FollowerPressure>(name, std::move(faces), field, q.get<double>("Ramp Time"),
                                            model.kinematics() == Kinematics::Axisymmetric, model.dofs(),
                                            components, *model.stiffness());
}

// The contact pairs, and the mass with the contact surfaces massless when redistributed.
void DirectTransient::buildContact(Model& model) {
  b_->contact = makeContactManager(s_.contact, model.mesh(), model.dofs(), model.map(), inputFile_,
                                   model.kinematics() == Kinematics::Axisymmetric);
  if (!s_.contact.redistributeMass) return;
  const std::vector<char> massless = b_->contact->surfaceNodes(model.mesh());
  for (char c : massless) b_->masslessNodes += c;
  try {
    b_->M = model.mass(massless);
  } catch (const std::invalid_argument& e) {
    if (!s_.contact.massIsAutomatic) throwInput(inputFile_, path("Contact Mass"), "redistributed", e.what());
    b_->masslessNodes = 0;
    b_->massFallback = e.what();
  }
}

// Central differences: the lumped mass's inverse and the critical step, refused or sub-stepped.
void DirectTransient::setupExplicit(const Model& model) {
  // The element bound holds for the mesh's own lumped mass (not for a redistributed one).
  const double meshBound = b_->masslessNodes == 0 ? model.eigenvalueBound()
                                                  : std::numeric_limits<double>::infinity();
  b_->explicitPlan = std::make_unique<ExplicitPlan>(planExplicit(
      {*b_->K, *b_->M, b_->contact.get(), b_->links.get(), meshBound, s_.rayleighK, s_.rayleighM,
       s_.time.timeStep, s_.time.endTime - s_.time.startTime, s_.stability, s_.output.limits, inputFile_, "Analyses/" + name_}));
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
  b_->condenseContact = s_.contact.condensable() && lp.get<std::string>("Method") != "Direct";
  std::shared_ptr<const NodalBlocks> blocks;
  // (An explicit run builds the solver without using it; multiplier rows were refused with the input.)
  if (lp.get<std::string>("Preconditioner") == "Multigrid" && lp.get<std::string>("Method") != "Direct")
    blocks = std::make_shared<const NodalBlocks>(nodalBlocks(model.dofs(), model.mesh().coords));
  try {
    b_->solver = makeLinearSolver(lp, symmetric, std::move(blocks));
  } catch (const InputError& e) {
    throwInput(inputFile_, path("Linear Solver"), "", e.what());
  }
}

// The stepper of the scheme: Newmark family (Newton) or central differences (explicit).
std::unique_ptr<StructuralStepper> DirectTransient::stepper(StructuralOperator& op) const {
  if (s_.explicitScheme) {
    op.storeStiffnessSymmetrically();  // one product with K per sub-step is the run's cost
    op.useDiagonalMass(b_->explicitPlan->massDiagonal);
    auto cd = std::make_unique<CentralDifferenceStepper>(op, b_->explicitPlan->inverseMass, s_.time,
                                                         b_->explicitPlan->substeps);
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
  return std::make_unique<NewmarkStepper>(op, s_.scheme, s_.time);
}

// The model's internal force: element by element when some block is finite-strain, else K u.
std::shared_ptr<InternalForce> DirectTransient::internalForce(Model& model) const {
  if (model.finiteStrain()) {
    auto f = std::make_shared<FiniteStrainForce>(model);
    if (b_->loads)
      for (const auto& p : b_->loads->followers()) f->addFollowerPressure(p);
    return f;
  }
  return std::make_shared<LinearElasticForce>(b_->K);
}

void DirectTransient::run(RunContext& ctx) {
  const auto wallStart = std::chrono::steady_clock::now();
  auto timer = rcp(new Teuchos::StackedTimer(("Transient '" + name_ + "'").c_str()));
  StructuralOperator op(internalForce(ctx.model), b_->M, s_.rayleighK, s_.rayleighM, b_->loads, b_->contact.get(),
                        b_->links.get(), std::move(b_->solver), timer.get());
  configure(op, ctx.model);
  describe(ctx.model, op);
  const StateArchive* resume = resumeFor(ctx);
  ObserverSet outputs;
  std::unique_ptr<ContactReport> report;
  if (b_->contact) report = std::make_unique<ContactReport>(*b_->contact, ctx.model.mesh().numNodes());
  const InteractionList interactions({report.get(), b_->links.get()});
  DirectStepView view(op, report.get(), interactions.simplest(), b_->probes, outputs, timer.get());
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
    recordFigures(loop.progress(), op, *timer, wallStart);
    summarizeCounts(ctx.summary, loop.progress(), op, loop.time());
    history.summarize(ctx.summary);
    throw;
  }
  timer->stopBaseTimer();
  reportRun(ctx, sum, op, *timer, wallStart, history);
}

// How the operator treats contact (forward increments, condensed), and the domain of its assembled
// small-strain blocks (checked with the elements' validity).
void DirectTransient::configure(StructuralOperator& op, Model& model) const {
  op.setForwardIncrementContact(s_.explicitScheme && s_.contact.forwardIncrementsWhenExplicit());
  op.setCondensedContact(!s_.explicitScheme && b_->condenseContact);
  auto domain = std::make_shared<SmallStrainDomain>(model);
  if (!domain->empty()) op.setSmallStrainDomain(domain);
}

// The view's records of a checkpoint's state, before the loop continues from it.
void DirectTransient::continueView(DirectStepView& view, const StateArchive& resume, const StateVectors& vectors,
                                   const Model& model) {
  view.restore(resume, vectors, model.map());
  log() << format("  continuing from the checkpoint at t = %.6e s (step %lld)\n", resume.getDouble("point/time"),
                  resume.getInt("point/nominal"));
}

// The figures of the run: recorded, logged, summarised (<name>.summary.json); then the checks.
void DirectTransient::reportRun(RunContext& ctx, const TransientSummary& sum, const StructuralOperator& op,
                               Teuchos::StackedTimer& timer, std::chrono::steady_clock::time_point start,
                               const HistoryObserver& history) {
  recordFigures(sum, op, timer, start);
  logFigures(sum, ctx.model, timer);
  summarize(ctx.summary, sum, op, *ctx.model.comm());
  history.summarize(ctx.summary);
  evaluateChecks(b_->checks, history.history(), ctx.checks);
  if (history.balance().failed()) ctx.checks.push_back(history.balance().checkResult(name_));
  if (history.hourglass().failed()) ctx.checks.push_back(history.hourglass().checkResult(name_));
}

void DirectTransient::summarize(RunSummary& s, const TransientSummary& sum, const StructuralOperator& op,
                                  const Comm& comm) const {
  summarizeCounts(s, sum, op, s_.time.endTime);
  const std::pair<const char*, double> timers[] = {{"assembly", figures_.assembly},
                                                   {"linear_solve", figures_.linearSolve},
                                                   {"contact", figures_.contact},
                                                   {"output", figures_.output},
                                                   {"analysis", figures_.wall}};
  for (const auto& [name, seconds] : timers) {  // min and max over the ranks (collective)
    double lo = 0, hi = 0;
    Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_MIN, seconds, Teuchos::outArg(lo));
    Teuchos::reduceAll<int, double>(comm, Teuchos::REDUCE_MAX, seconds, Teuchos::outArg(hi));
    s.set(std::string("timers/") + name + "/min", lo);
    s.set(std::string("timers/") + name + "/max", hi);
  }
}

void DirectTransient::summarizeCounts(RunSummary& s, const TransientSummary& sum, const StructuralOperator& op,
                                      double timeReached) const {
  s.set("scheme", s_.explicitScheme ? std::string("central differences") : s_.scheme.name());
  s.set("time_step", s_.time.timeStep);
  s.set("end_time", s_.time.endTime);
  s.set("steps", sum.steps);
  s.set("smallest_step", sum.smallestStep);
  s.set("time_reached", timeReached);
  if (s_.explicitScheme) {
    s.set("substeps_per_step", b_->explicitPlan->substeps);  // at the start
    s.set("substep", s_.time.timeStep / b_->explicitPlan->substeps);
    s.set("substeps_taken", sum.substeps);  // in all: the deformed mesh's estimates may change the count
    s.set("substeps_largest", sum.maxSubsteps);
    s.set("critical_step", b_->explicitPlan->criticalStep);
    s.set("frequency_bound/omega_max", b_->explicitPlan->bound.omegaMax);
    s.set("frequency_bound/element", b_->explicitPlan->bound.element);
    s.set("frequency_bound/gershgorin", b_->explicitPlan->bound.gershgorin);
  } else {
    s.set("newton/iterations", sum.newtonIterations);
    s.set("newton/max_per_step", sum.maxNewtonPerStep);
    s.set("newton/backtracks", sum.backtracks);
    s.set("active_set_passes", sum.activeSetIterations);
    s.set("failed_attempts", sum.failedSteps);
    s.set("factorizations", figures_.refactorizations);
    s.set("kept_factorizations", figures_.keptFactorizations);
    s.set("krylov_iterations", sum.krylovIterations);
    s.set("linear_solver/description", op.solver().description());
    s.set("linear_solver/choice", b_->solverChoice);
  }
  if (b_->contact) {
    s.set("contact/method", s_.contact.methodName());
    s.set("contact/constraints", b_->contact->numConstraints());
  }
}

namespace {

// " (+ n contact pressures[, how they leave the Newton system])", or "" without multipliers.
std::string pressuresClause(const ContactManager* contact, const StructuralOperator& op) {
  if (!contact || !contact->method().hasMultipliers()) return "";
  const char* how = op.condensedContact()   ? ", condensed out of the Newton system node by node"
                    : op.projectedContact() ? ", projected out of the Newton system (C^T du = t by P = I - C (C^T C)^-1 C^T)"
                                            : "";
  return " (+ " + std::to_string(contact->numConstraints()) + " contact pressures" + how + ")";
}

}  // namespace

void DirectTransient::describe(Model& model, const StructuralOperator& op) const {
  const ContactManager* contact = b_->contact.get();
  log() << "  " << model.dofs().numGlobal() << " unknowns" << pressuresClause(contact, op)
        << "; " << (s_.explicitScheme ? std::string("central differences (explicit, lumped mass)")
                                         : s_.scheme.describe())
        << "\n";
  if (s_.explicitScheme)
    log() << format("  critical step %.4e s (highest frequency at most %.4e rad/s: mesh, penalty contact, "
                    "links; element bound %.4e, Gershgorin's %.4e); dt = %.4e s: %d sub-step(s) per "
                    "step\n",
                    b_->explicitPlan->criticalStep, b_->explicitPlan->bound.omegaMax, b_->explicitPlan->bound.element, b_->explicitPlan->bound.gershgorin,
                    s_.time.timeStep, b_->explicitPlan->substeps);
  if (b_->explicitPlan && !b_->explicitPlan->stabilityWarning.empty())
    log() << "  warning: " << b_->explicitPlan->stabilityWarning << "\n";
  log() << "  dt = " << s_.time.timeStep << " s"
        << (s_.time.startTime != 0 ? " from " + shortNumber(s_.time.startTime) + " s" : std::string()) << " to "
        << s_.time.endTime << " s; Rayleigh C = "
        << s_.rayleighK << " K + " << s_.rayleighM << " M; "
        << (s_.explicitScheme ? std::string("no linear solve") : "linear solver " + op.solver().description())
        << (s_.explicitScheme || b_->solverChoice.empty() ? std::string() : " (" + b_->solverChoice + ")")
        << "\n";
  if (b_->masslessNodes > 0) {
    // 1^T M 1 over the free DOFs (the mass summed over the free directions), before and after.
    Vector one(model.map()), y(model.map());
    one.putScalar(1.0);
    model.mass()->apply(one, y);
    const double before = one.dot(y);
    b_->M->apply(one, y);
    log() << format("  contact mass: redistributed: %lld contact-surface nodes massless (%lld DOFs); "
                    "1^T M 1 over the free DOFs (the mass once per free direction: 3 x the mass in "
                    "3D with every direction free) %.12g -> %.12g kg\n",
                    b_->masslessNodes, op.masslessDofs(), before, one.dot(y));
  }
  if (!b_->massFallback.empty())
    log() << "  contact mass: standard ('auto' could not redistribute it: " << b_->massFallback << ")\n";
  if (contact) {
    log() << "  contact: " << contact->method().name() << ", " << contact->numConstraints()
          << " slave nodes paired";
    if (contact->unpairedNodes() > 0) log() << " (" << contact->unpairedNodes() << " unpaired)";
    if (contact->hasFriction())
      log() << format("; Coulomb friction, stick stiffness k_t = %.4g N/m per node%s",
                      contact->tangentialStiffness(),
                      s_.contact.tangentialStiffness > 0 ? "" : " (the stiffest node's mean diagonal of K)");
    log() << "\n";
  }
  if (b_->links) {
    log() << "  shock links (penalty law, tangent by central differences):";
    for (const ShockLink& l : b_->links->links())
      log() << " " << l.name << " (node " << l.node1 + 1
            << (l.node2 >= 0 ? " to node " + std::to_string(l.node2 + 1) : std::string(" to a fixed obstacle"))
            << ")";
    log() << "\n";
  }
}

void DirectTransient::recordFigures(const TransientSummary& sum, const StructuralOperator& op,
                                      const Teuchos::StackedTimer& timer,
                                      std::chrono::steady_clock::time_point start) {
  figures_.steps = sum.steps;
  figures_.newtonIterations = sum.newtonIterations;
  figures_.refactorizations = op.factorizations();
  figures_.keptFactorizations = op.keptFactorizations();
  figures_.activeSetIterations = sum.activeSetIterations;
  figures_.maxNewtonPerStep = sum.maxNewtonPerStep;
  figures_.failedSteps = sum.failedSteps;
  figures_.unknowns = op.unknowns();
  auto& t = const_cast<Teuchos::StackedTimer&>(timer);  // accumulatedTime is not const
  figures_.assembly = t.accumulatedTime("Transient: assembly");
  figures_.linearSolve = t.accumulatedTime("Transient: linear solve");
  figures_.contact = t.accumulatedTime("Transient: contact");
  figures_.output = t.accumulatedTime("Transient: output");
  figures_.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void DirectTransient::logFigures(const TransientSummary& sum, const Model& model,
                                   Teuchos::StackedTimer& timer) const {
  const Figures& f = figures_;
  if (s_.explicitScheme && sum.maxSubsteps > b_->explicitPlan->substeps)
    log() << format("  %d steps, %lld sub-steps in all (%d per step at the start, up to %d on the deformed "
                    "mesh; the smallest %.3e s), no linear solve\n",
                    sum.steps, sum.substeps, b_->explicitPlan->substeps, sum.maxSubsteps, sum.smallestStep);
  else if (s_.explicitScheme) {
    const double each = s_.time.timeStep / b_->explicitPlan->substeps;  // the last step may be cut to End Time
    const std::string last = sum.smallestStep < each * (1 - 1e-9)
                                 ? format("; the last step's %.3e s", sum.smallestStep) : std::string();
    log() << format("  %d steps of %d sub-step(s) (%.3e s each%s), no linear solve\n", sum.steps,
                    b_->explicitPlan->substeps, each, last.c_str());
  }
  else
    log() << format("  %d steps, %d Newton iterations (%.2f per step, at most %d), %d active-set "
                    "passes, %d factorisations%s, %d failed attempts (smallest dt %.3e s)\n",
                    sum.steps, sum.newtonIterations, double(sum.newtonIterations) / std::max(1, sum.steps),
                    sum.maxNewtonPerStep, sum.activeSetIterations, f.refactorizations,
                    f.keptFactorizations > 0
                        ? format(" (%d changes of contact status solved on the factorisation kept, see "
                                 "Update Budget)", f.keptFactorizations).c_str()
                        : "",
                    sum.failedSteps, sum.smallestStep);
  if (sum.backtracks > 0)
    log() << format("  %d Newton correction(s) halved because they inverted an element\n", sum.backtracks);
  if (b_->links && b_->links->dashpotDrops() > 0)
    log() << format("  shock links: a dashpot was dropped in %lld step(s): closing while approaching, the "
                    "law's force jumps and the step had no solution with it\n",
                    b_->links->dashpotDrops());
  if (sum.krylovIterations > 0)
    log() << format("  Krylov iterations: %d (%.1f per step, %.1f per Newton solve)\n",
                    sum.krylovIterations, double(sum.krylovIterations) / std::max(1, sum.steps),
                    double(sum.krylovIterations) / std::max(1, sum.newtonIterations));
  log() << format("  time: %.3f s = assembly %.3f + linear solve %.3f + contact %.3f + output %.3f "
                  "+ other (rank 0)\n",
                  f.wall, f.assembly, f.linearSolve, f.contact, f.output);
  std::ostringstream rep;
  Teuchos::StackedTimer::OutputOptions opt;
  opt.output_minmax = model.comm()->getSize() > 1;
  opt.output_fraction = true;
  opt.print_warnings = false;
  timer.report(rep, model.comm(), opt);
  log() << rep.str();
}

}  // namespace choc
