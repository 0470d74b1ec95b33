// The run's description and figures of a direct transient (TransientReport.hpp).
#include "observers/TransientReport.hpp"

#include <algorithm>
#include <sstream>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "contact/ContactManager.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"

namespace choc {

void TransientReport::summarize(RunSummary& s, const TransientSummary& sum, const Comm& comm) const {
  summarizeCounts(s, sum, f_.endTime);
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

void TransientReport::summarizeCounts(RunSummary& s, const TransientSummary& sum, double timeReached) const {
  s.set("scheme", f_.explicitScheme ? std::string("central differences") : f_.schemeName);
  s.set("time_step", f_.timeStep);
  s.set("end_time", f_.endTime);
  s.set("steps", sum.steps);
  s.set("smallest_step", sum.smallestStep);
  s.set("time_reached", timeReached);
  if (f_.explicitScheme) {
    s.set("substeps_per_step", f_.substeps);  // at the start
    s.set("substep", f_.timeStep / f_.substeps);
    s.set("substeps_taken", sum.substeps);  // in all: the deformed mesh's estimates may change the count
    s.set("substeps_largest", sum.maxSubsteps);
    s.set("critical_step", f_.criticalStep);
    s.set("frequency_bound/omega_max", f_.bound.omegaMax);
    s.set("frequency_bound/element", f_.bound.element);
    s.set("frequency_bound/gershgorin", f_.bound.gershgorin);
  } else {
    s.set("newton/iterations", sum.newtonIterations);
    s.set("newton/max_per_step", sum.maxNewtonPerStep);
    s.set("newton/backtracks", sum.backtracks);
    s.set("active_set_passes", sum.activeSetIterations);
    s.set("failed_attempts", sum.failedSteps);
    s.set("factorizations", figures_.refactorizations);
    s.set("kept_factorizations", figures_.keptFactorizations);
    s.set("krylov_iterations", sum.krylovIterations);
    s.set("linear_solver/description", op_.correction().solver().description());
    s.set("linear_solver/choice", f_.solverChoice);
  }
  if (contact_) {
    s.set("contact/method", f_.contactMethod);
    s.set("contact/constraints", contact_->numConstraints());
  }
}

namespace {

// " (+ n contact pressures[, how they leave the Newton system])", or "" without multipliers.
std::string pressuresClause(const ContactManager* contact, const StructuralOperator& op) {
  if (!contact || !contact->method().hasMultipliers()) return "";
  const std::string how = op.contact() ? op.contact()->pressuresNote() : "";
  return " (+ " + std::to_string(contact->numConstraints()) + " contact pressures" + how + ")";
}

}  // namespace

void TransientReport::describe(Model& model, const CrsMatrix& runMass) const {
  const ContactManager* contact = contact_;
  log() << "  " << model.dofs().numGlobal() << " unknowns" << pressuresClause(contact, op_)
        << "; " << (f_.explicitScheme ? std::string("central differences (explicit, lumped mass)")
                                         : f_.schemeDescription)
        << "\n";
  if (f_.explicitScheme)
    log() << format("  critical step %.4e s (highest frequency at most %.4e rad/s: mesh, penalty contact, "
                    "links; element bound %.4e, Gershgorin's %.4e); dt = %.4e s: %d sub-step(s) per "
                    "step\n",
                    f_.criticalStep, f_.bound.omegaMax, f_.bound.element, f_.bound.gershgorin,
                    f_.timeStep, f_.substeps);
  if (!f_.stabilityWarning.empty())
    log() << "  warning: " << f_.stabilityWarning << "\n";
  log() << "  dt = " << f_.timeStep << " s"
        << (f_.startTime != 0 ? " from " + shortNumber(f_.startTime) + " s" : std::string()) << " to "
        << f_.endTime << " s; Rayleigh C = "
        << f_.rayleighK << " K + " << f_.rayleighM << " M; "
        << (f_.explicitScheme ? std::string("no linear solve") : "linear solver " + op_.correction().solver().description())
        << (f_.explicitScheme || f_.solverChoice.empty() ? std::string() : " (" + f_.solverChoice + ")")
        << "\n";
  if (f_.masslessNodes > 0) {
    // 1^T M 1 over the free DOFs (the mass summed over the free directions), before and after.
    Vector one(model.map()), y(model.map());
    one.putScalar(1.0);
    model.mass()->apply(one, y);
    const double before = one.dot(y);
    runMass.apply(one, y);
    const bool normal = !op_.mass().masslessRotation().is_null();
    log() << format("  contact mass: %s: %lld contact-surface nodes massless%s (%lld DOFs); "
                    "1^T M 1 over the free DOFs (the mass once per free direction: 3 x the mass in "
                    "3D with every direction free) %.12g -> %.12g kg\n",
                    normal ? "normal" : "redistributed", f_.masslessNodes,
                    normal ? " along their normals" : "", op_.mass().masslessDofs(), before, one.dot(y));
  }
  if (!f_.massChoice.empty()) log() << "  contact mass: " << f_.massChoice << "\n";
  if (!f_.massFallback.empty())
    log() << "  contact mass: standard ('auto' could not redistribute it: " << f_.massFallback << ")\n";
  if (contact) {
    log() << "  contact: " << contact->method().name() << ", " << contact->numConstraints()
          << " slave nodes paired";
    if (contact->unpairedNodes() > 0) log() << " (" << contact->unpairedNodes() << " unpaired)";
    if (contact->hasFriction())
      log() << format("; Coulomb friction, stick stiffness k_t = %.4g N/m per node%s",
                      contact->friction()->tangentialStiffness(),
                      f_.givenTangentialStiffness ? "" : " (the stiffest node's mean diagonal of K)");
    log() << "\n";
  }
  if (links_) {
    log() << "  shock links (penalty law, tangent by central differences):";
    for (const ShockLink& l : links_->links())
      log() << " " << l.name << " (node " << l.node1 + 1
            << (l.node2 >= 0 ? " to node " + std::to_string(l.node2 + 1) : std::string(" to a fixed obstacle"))
            << ")";
    log() << "\n";
  }
}


void TransientReport::record(const TransientSummary& sum, const Teuchos::StackedTimer& timer,
                             std::chrono::steady_clock::time_point start) {
  figures_.steps = sum.steps;
  figures_.newtonIterations = sum.newtonIterations;
  figures_.refactorizations = op_.correction().factorizations();
  figures_.keptFactorizations = op_.correction().keptFactorizations();
  figures_.activeSetIterations = sum.activeSetIterations;
  figures_.maxNewtonPerStep = sum.maxNewtonPerStep;
  figures_.failedSteps = sum.failedSteps;
  figures_.unknowns = op_.correction().unknowns(int(op_.map()->getGlobalNumElements()));
  auto& t = const_cast<Teuchos::StackedTimer&>(timer);  // accumulatedTime is not const
  figures_.assembly = t.accumulatedTime("Transient: assembly");
  figures_.linearSolve = t.accumulatedTime("Transient: linear solve");
  figures_.contact = t.accumulatedTime("Transient: contact");
  figures_.output = t.accumulatedTime("Transient: output");
  figures_.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}


void TransientReport::logFigures(const TransientSummary& sum, const Model& model, Teuchos::StackedTimer& timer) const {
  const TransientFigures& f = figures_;
  if (f_.explicitScheme && sum.maxSubsteps > f_.substeps)
    log() << format("  %d steps, %lld sub-steps in all (%d per step at the start, up to %d on the deformed "
                    "mesh; the smallest %.3e s), no linear solve\n",
                    sum.steps, sum.substeps, f_.substeps, sum.maxSubsteps, sum.smallestStep);
  else if (f_.explicitScheme) {
    const double each = f_.timeStep / f_.substeps;  // the last step may be cut to End Time
    const std::string last = sum.smallestStep < each * (1 - 1e-9)
                                 ? format("; the last step's %.3e s", sum.smallestStep) : std::string();
    log() << format("  %d steps of %d sub-step(s) (%.3e s each%s), no linear solve\n", sum.steps,
                    f_.substeps, each, last.c_str());
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
  if (links_ && links_->dashpotDrops() > 0)
    log() << format("  shock links: a dashpot was dropped in %lld step(s): closing while approaching, the "
                    "law's force jumps and the step had no solution with it\n",
                    links_->dashpotDrops());
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
