// The parameters of a Transient (Analyses/<name> with Type = Transient) and their documentation.
#include "analysis/DirectTransient.hpp"
#include "input/ParameterSpec.hpp"
#include "solvers/SolverChoice.hpp"
#include "timeint/NewmarkStepper.hpp"

namespace choc {

namespace {

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
  declareChoice(nw, "Massless Start", "extrapolated", {"extrapolated", "predictor"},
                "where each step's Newton starts the DOFs without inertia (the contact surfaces of "
                "the redistributed contact mass, whose equations are static): 'extrapolated' from "
                "their last two increments (quadratic in time; the same solution, and a frictional "
                "contact layer's stick and slip start near it: the block dropped on the slab, "
                "input/block_on_slab.xml, 3.20 corrections per step against 5.35); 'predictor' at "
                "the Newmark predictor like every other DOF");
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

void declareCouplingLoads(ParameterList& p, const char* ramp) {
  ParameterList& cl = declareNamedSublists(
      p, "Coupling Loads",
      "a force and a moment on a distributing coupling (Model/Couplings), spread over its nodes in their "
      "current positions, by name");
  declareRequiredString(cl, "Coupling", "name of an entry of Model/Couplings");
  declareString(cl, "Force", "0 0 0", "force 'fx fy fz' [N] at the coupling's nodes' centroid (its direction fixed)");
  declareString(cl, "Moment", "0 0 0",
                "moment 'mx my mz' [N m] about the centroid (its direction fixed; a pure couple however the "
                "nodes move)");
  declareDouble(cl, "Ramp Time", 0.0, ramp, Range::nonNegative());
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
  declareCouplingLoads(p, ramp);
  declareString(p, "Gravity", "0 0 0",
                "the acceleration of gravity 'gx gy gz' [m/s^2] (e.g. '0 0 -9.81'): the body force rho g on every "
                "block from t = 0 (the mass matrix times g on deformable blocks, m g at the centre of each rigid "
                "body), its work in the energy balance");
  declareInitialConditions(p);
  declareTransientOutput(p);
  declareChecks(p);
  return p;
}

}  // namespace choc
