// The factory of contact strategies and its refusals (contact/ContactStrategies.hpp).
#include "contact/ContactStrategies.hpp"

#include "core/Errors.hpp"
#include "core/Format.hpp"

namespace choc {

namespace {

// Multipliers on rows of their own in an implicit solve (not condensed nor projected).
bool saddlePoint(const ContactSettings& s) { return s.hasMultipliers() && !s.condensable(); }

void checkExplicit(const ContactSettings& s, const std::string& file) {
  if (s.velocityUpdate || s.normalMass)
    throwInput(file, s.path + "/Contact Mass", s.velocityUpdate ? "velocity update" : "normal",
               "is an implicit scheme's treatment (central differences enforce contact on the lumped mass)",
               "use 'standard' or 'auto' with central differences");
  if (s.hasPressureUnknowns())
    throwInput(file, s.path + "/Contact/Method", s.methodName(),
               "has pressure unknowns, which the explicit scheme (central differences) cannot solve for",
               "use Lagrange (forward-increment multipliers) or Penalty with central differences");
  if (const PairDefinition* fp = s.frictionPair(); fp && !s.forwardIncrementsWhenExplicit())
    throwInput(file, s.path + "/Contact/Pairs/" + fp->name + "/Friction Coefficient", shortNumber(fp->friction),
               "central differences apply friction by forward increments of Lagrange contact, not with '" +
                   s.methodName() + "' contact",
               "use 'Contact/Method' = Lagrange, or an implicit scheme (HHT, Newmark...)");
}

void checkImplicit(const ContactSettings& s, const ContactSolveChoice& c, const std::string& file) {
  if (const PairDefinition* fp = s.frictionPair(); fp && c.linearMethod == "CG")
    throwInput(file, s.path + "/Contact/Pairs/" + fp->name + "/Friction Coefficient", shortNumber(fp->friction),
               "the tangent of a sliding node is not symmetric, which CG cannot solve",
               "use 'Linear Solver/Method' = Direct or GMRES with friction");
  if (!saddlePoint(s)) return;
  const std::string which = "' between meshed bodies";
  if (c.linearMethod == "CG")
    throwInput(file, s.path + "/Linear Solver/Method", "CG",
               "the saddle-point system of contact method '" + s.methodName() + which + " is indefinite",
               "use Direct, GMRES or MINRES (or the Penalty method with CG)");
  if (c.preconditioner == "Multigrid" && c.linearMethod != "Direct")
    throwInput(file, s.path + "/Linear Solver/Preconditioner", "Multigrid",
               "the Newton matrix of contact method '" + s.methodName() + which +
                   " has multiplier rows, which multigrid for elasticity does not aggregate",
               "use the Penalty method with Multigrid, or Method = Direct or auto");
}

}  // namespace

void checkContactChoice(const ContactSettings& s, const ContactSolveChoice& c, const std::string& file) {
  if (c.explicitScheme)
    checkExplicit(s, file);
  else
    checkImplicit(s, c, file);
}

std::unique_ptr<ContactStrategy> makeContactStrategy(const ContactSettings& s, ContactManager& geometry,
                                                     const ContactSolveChoice& c) {
  std::unique_ptr<ContactStrategy> strategy;
  bool obstacles = true;
  for (const PairDefinition& p : s.pairs) obstacles = obstacles && p.hasObstacle;
  if (!s.hasMultipliers())
    strategy = std::make_unique<PenaltyStrategy>(geometry);
  else if (c.explicitScheme)
    strategy = std::make_unique<ForwardIncrementStrategy>(geometry);  // Lagrange (checked)
  else if (!s.condensable() || c.linearMethod == "Direct")
    strategy = std::make_unique<SaddlePointStrategy>(geometry);
  else if (obstacles)
    strategy = std::make_unique<CondensedStrategy>(geometry);
  else
    strategy = std::make_unique<ProjectedStrategy>(geometry);  // Lagrange with a pair between meshed bodies
  strategy->useVelocityUpdate(s.velocityUpdate);
  return strategy;
}

}  // namespace choc
