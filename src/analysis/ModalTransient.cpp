#include "analysis/ModalTransient.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "analysis/EnergyBalance.hpp"
#include "analysis/HistoryChecks.hpp"
#include "analysis/HistoryProbes.hpp"
#include "analysis/InitialConditions.hpp"
#include "analysis/ModalLinks.hpp"
#include "analysis/ModalProjection.hpp"
#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"
#include "input/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "output/ExodusResults.hpp"
#include "output/HistoryCsv.hpp"
#include "output/Interrupt.hpp"
#include "output/Log.hpp"

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
  declareChoice(p, "Stability Check", "refuse", {"refuse", "warn", "substep"},
                "when dt exceeds the critical step (modes + link stiffness): refuse the run, "
                "warn and go on, or sub-step each step (at 0.9 of the critical step, 0.5 with "
                "penalty links)");
  declareChoice(p, "Projection", "mass-weighted", {"mass-weighted", "least-squares"},
                "projection of the initial fields on the basis");
  declareString(p, "History", "", "history quantities '<node set>:<DX|VX|AX...>', e.g. 'A:DX A:VX'");
  declareInt(p, "Exodus Interval", 10, "write the Exodus fields every N steps (0: never)",
             Range::atLeast(0));
  declareInt(p, "Progress Lines", 10, "progress lines printed during the run", Range::atLeast(0));
  declareEnergyBalance(p);
  declareInitialConditions(p);
  declareShockLinks(p);
  declareChecks(p);
  return p;
}

namespace {

std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

std::vector<double> parseList(const std::string& text, const std::string& file,
                              const std::string& param) {
  std::vector<double> v;
  std::istringstream in(text);
  std::string tok;
  while (in >> tok) {
    char* end = nullptr;
    const double x = std::strtod(tok.c_str(), &end);
    if (*end || !(x >= 0 && x < 1)) throwInput(file, param, tok, "not a damping ratio in [0, 1)");
    v.push_back(x);
  }
  return v;
}

}  // namespace

void ModalTransient::run(RunContext& ctx) {
  Model& model = ctx.model;
  const std::string& file = inputFile_;
  const std::string basisName = params_.get<std::string>("Modal Basis");
  auto it = ctx.bases.find(basisName);
  if (it == ctx.bases.end())
    throwInput(file, path("Modal Basis"), basisName, "no modal basis of that name has been computed",
               "name a Modal analysis listed before this one in Analyses");
  const ModalBasis& basis = *it->second;
  const int nm = static_cast<int>(basis.eigenvalues.size());

  // Generalized stiffness and damping.
  std::vector<double> w2(nm), c(nm), xi(nm, params_.get<double>("Modal Damping"));
  const std::string list = params_.get<std::string>("Modal Damping List");
  if (!list.empty()) {
    xi = parseList(list, file, path("Modal Damping List"));
    if (static_cast<int>(xi.size()) != nm)
      throwInput(file, path("Modal Damping List"), list,
                 "has " + std::to_string(xi.size()) + " values for " + std::to_string(nm) + " modes");
  }
  const double fRigid = params_.get<double>("Rigid Body Frequency");
  int rigid = 0;
  double w2max = 0.0, ximax = 0.0;
  for (int k = 0; k < nm; ++k) {
    w2[k] = std::max(0.0, basis.eigenvalues[k]);
    if (basis.frequencyHz(k) < fRigid) {
      xi[k] = 0.0;
      ++rigid;
    }
    c[k] = 2.0 * xi[k] * std::sqrt(w2[k]);
    w2max = std::max(w2max, w2[k]);
    ximax = std::max(ximax, xi[k]);
  }

  // Initial state.
  const InitialFields init = buildInitialFields(params_, model, "Analyses/" + name_);
  const std::string proj = params_.get<std::string>("Projection");
  ModalState state;
  state.q = projectOnBasis(*basis.vectors, *model.mass(), *init.displacement, proj);
  state.v = projectOnBasis(*basis.vectors, *model.mass(), *init.velocity, proj);
  const double resU = projectionResidual(*basis.vectors, *init.displacement, state.q);
  const double resV = projectionResidual(*basis.vectors, *init.velocity, state.v);

  ModalLinks links(params_, model, basis, "Analyses/" + name_);
  const std::vector<Probe> probes =
      parseProbes(params_.get<std::string>("History"), model, path("History"));
  std::vector<long long> probeDofs;
  for (const auto& p : probes) probeDofs.push_back(p.dof);
  const std::vector<double> probeRows = gatherRows(*basis.vectors, probeDofs);

  // Time grid and stability.
  const double t0 = params_.get<double>("Start Time"), tEnd = params_.get<double>("End Time");
  double dt = params_.get<double>("Time Step");
  if (!(tEnd > t0)) throwInput(file, path("End Time"), number(tEnd), "must exceed the Start Time");
  const double ratio = (tEnd - t0) / dt;
  const long long nsteps = std::llround(ratio);
  if (nsteps < 1 || std::abs(ratio - nsteps) > 1e-6 * std::max(1.0, ratio))
    throwInput(file, path("Time Step"), number(dt),
               "does not divide End Time - Start Time into whole steps",
               "choose dt = (End - Start) / N");
  const double omegaMax = std::sqrt(w2max + links.linkOmega2Bound());
  const double dtCrit = explicitCriticalStep(omegaMax, std::max(ximax, links.linkDampingRatioBound()));
  int substeps = 1;
  const std::string stab = params_.get<std::string>("Stability Check");
  const ModalScheme scheme = parseModalScheme(params_.get<std::string>("Scheme"));
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "  %lld unknowns; basis '%s': %d modes (%d rigid), %.1f Hz to %.1f Hz; %zu link(s)\n"
                "  projection (%s) residual: displacement %.2e, velocity %.2e\n"
                "  critical step %.4e s (modes + link stiffness), dt = %.4e s, %lld steps\n",
                model.dofs().numGlobal(), basisName.c_str(), nm, rigid, basis.frequencyHz(0),
                basis.frequencyHz(nm - 1), links.links().size(), proj.c_str(), resU, resV, dtCrit,
                dt, nsteps);
  log() << buf;
  if (dt > dtCrit) {
    std::snprintf(buf, sizeof buf, "%.4e s exceeds the critical step %.4e s of the explicit scheme",
                  dt, dtCrit);
    if (stab == "refuse")
      throwInput(file, path("Time Step"), number(dt), buf,
                 "reduce dt, or set 'Stability Check' to 'substep'");
    if (stab == "warn") log() << "  warning: " << buf << "\n";
    if (stab == "substep") {
      // Penalty links: the critical step is a linear-stability bound, but each closing of a
      // stiff link is a nonlinear event that can add energy near the limit (a 1e16 N/m link
      // doubled the energy at 0.9 of it, ~1% at 0.5): sub-step at half of it then.
      bool penalty = false;
      for (const auto& l : links.links()) penalty = penalty || !l.law.rigid;
      substeps = static_cast<int>(std::ceil(dt / ((penalty ? 0.5 : 0.9) * dtCrit)));
      log() << "  " << buf << ": " << substeps << " sub-steps per step\n";
    }
  }

  // Outputs.
  std::vector<std::string> columns;
  for (const auto& p : probes) columns.push_back(p.column);
  for (const char* e : {"energy:kinetic", "energy:strain", "energy:contact", "energy:dissipated",
                        "energy:total", "energy:balance"})
    columns.push_back(e);
  for (const auto& l : links.links()) {
    columns.push_back(l.name + ":force");
    columns.push_back(l.name + ":gap");
    columns.push_back(l.name + ":status");
  }
  verifyChecks(params_, columns, tEnd, file, "Analyses/" + name_);
  const std::string base = ctx.outputDir + "/" + name_;
  std::unique_ptr<HistoryCsv> history;
  std::unique_ptr<ExodusResultsWriter> exo;
  const int exoEvery = params_.get<int>("Exodus Interval");
  std::vector<std::string> globals = {"KINETIC_ENERGY", "STRAIN_ENERGY", "CONTACT_ENERGY",
                                      "TOTAL_ENERGY"};
  for (const auto& l : links.links()) {
    globals.push_back(l.name + "_FORCE");
    globals.push_back(l.name + "_GAP");
    globals.push_back(l.name + "_STATUS");
  }
  if (isRootRank()) {
    history = std::make_unique<HistoryCsv>(base + ".history.csv", columns);
    if (exoEvery > 0)
      exo = std::make_unique<ExodusResultsWriter>(
          base + ".exo", model.mesh(),
          std::vector<std::string>{"DISP_X", "DISP_Y", "DISP_Z", "VEL_X", "VEL_Y", "VEL_Z",
                                   "ACC_X", "ACC_Y", "ACC_Z"},
          globals);
  }

  ModalIntegrator integrator(scheme, w2, c, links, params_.get<int>("Refinement Factor"));
  integrator.initialize(state, t0);
  RecordedHistory rec;
  // No external loads in a modal transient (obstacles are fixed): W_external = 0.
  EnergyBalanceMonitor balance(params_, "modal transient '" + name_ + "'");
  std::vector<double> row(columns.size() - 0);
  Vector field(model.map());

  auto probeValue = [&](size_t i, const std::vector<double>& x) {
    double s = 0.0;
    const double* r = &probeRows[i * nm];
    for (int k = 0; k < nm; ++k) s += r[k] * x[k];
    return s;
  };
  auto record = [&](long long step) {
    size_t j = 0;
    const std::vector<double> vsync = integrator.synchronizedVelocity(state);
    for (size_t i = 0; i < probes.size(); ++i) {
      // Velocities: the scheme's own v for symplectic Euler (as the reference deck reports
      // it), the synchronized one (with the constraint impulse) for the other schemes.
      const auto& x = probes[i].field == ProbeField::Displacement ? state.q
                      : probes[i].field == ProbeField::Velocity
                          ? (scheme == ModalScheme::SymplecticEuler ? state.v : vsync)
                          : state.a;
      row[j++] = probeValue(i, x);
    }
    double ek = 0.0, es = 0.0;
    const std::vector<double> vs = integrator.synchronizedVelocity(state);
    for (int k = 0; k < nm; ++k) {
      ek += 0.5 * vs[k] * vs[k];
      es += 0.5 * w2[k] * state.q[k] * state.q[k];
    }
    const double ec = links.springEnergy();
    const double ed = integrator.modalDissipation() + links.dissipatedEnergy();
    row[j++] = ek;
    row[j++] = es;
    row[j++] = ec;
    row[j++] = ed;
    row[j++] = ek + es + ec;
    row[j++] = balance.update(state.t, ek + es + ec, ed, 0.0);
    for (const auto& l : links.links()) {
      row[j++] = l.last.normalForce;
      row[j++] = l.last.gap;
      row[j++] = l.last.closed ? 1.0 : 0.0;
    }
    for (size_t i = 0; i < row.size(); ++i)
      if (!std::isfinite(row[i])) {
        std::snprintf(buf, sizeof buf, "%.6e s (%s = %g; unstable time step?)", state.t,
                      columns[i].c_str(), row[i]);
        throw NumericalError("modal transient '" + name_ + "': the solution is not finite at t = " + buf);
      }
    rec.times.push_back(state.t);
    for (size_t i = 0; i < columns.size(); ++i) rec.columns[columns[i]].push_back(row[i]);
    if (history) history->appendRow(state.t, row);
    if (exoEvery > 0 && step % exoEvery == 0) {
      std::vector<std::vector<double>> nodal;
      for (const auto* x : {&state.q, &state.v, &state.a}) {
        field.putScalar(0.0);
        for (int k = 0; k < nm; ++k) field.update((*x)[k], *basis.vectors->getVector(k), 1.0);
        const auto all = gatherAll(field, 0, model.dofs());
        for (int cpt : {DX, DY, DZ}) nodal.push_back(nodalComponent(all, model.dofs(), cpt));
      }
      std::vector<double> g = {row[probes.size()], row[probes.size() + 1], row[probes.size() + 2],
                               row[probes.size() + 4]};
      for (const auto& l : links.links()) {
        g.push_back(l.last.normalForce);
        g.push_back(l.last.gap);
        g.push_back(l.last.closed ? 1.0 : 0.0);
      }
      if (exo) exo->writeStep(state.t, nodal, g);
    }
  };

  const int progressLines = params_.get<int>("Progress Lines");
  const long long progressEvery = progressLines > 0 ? std::max(1LL, nsteps / progressLines) : 0;
  const auto loopStart = std::chrono::steady_clock::now();
  // SIGINT/SIGTERM stop the run at a step boundary (every step on one rank; on several, every
  // 50 steps, since the check is then a reduction).
  const long long interruptEvery = model.comm()->getSize() > 1 ? 50 : 1;
  const std::string what = "modal transient '" + name_ + "'";
  try {
    record(0);
    for (long long n = 1; n <= nsteps; ++n) {
      if (n % interruptEvery == 0) throwIfInterrupted(what, state.t, model.rawComm());
      integrator.advance(state, dt, substeps);
      state.t = t0 + n * dt;
      record(n);
      if (progressEvery && n % progressEvery == 0) {
        std::snprintf(buf, sizeof buf, "  step %7lld/%lld  t = %.4e s", n, nsteps, state.t);
        log() << buf;
        for (const auto& l : links.links())
          log() << "  " << l.name << (l.last.closed ? " closed" : " open") << " F = " << l.last.normalForce;
        log() << "\n";
      }
    }
  } catch (...) {
    std::string kept;
    if (history && history->open()) kept += " " + incompletePath(history->path());
    if (exo) kept += " " + exo->incompletePath();
    if (history) history->abandon();
    if (exo) exo->abandon();
    log() << "  run stopped at t = " << state.t << " s; partial results (complete up to that time)"
          << (kept.empty() ? std::string(": none") : ":" + kept) << "\n";
    throw;
  }
  if (history) history->finish();
  if (exo) exo->finish();
  const double loop =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - loopStart).count();
  std::snprintf(buf, sizeof buf,
                "  %lld steps, %lld sub-steps in %.4f s (%.2f us per step, output included); "
                "history %s.history.csv\n",
                nsteps, integrator.subStepsTaken(), loop, 1e6 * loop / nsteps, base.c_str());
  log() << buf;
  log() << balance.summary();

  auto results = evaluateDeclaredChecks(params_, rec, name_);
  auto exact = compareWithExact(params_, rec, model, name_, "Analyses/" + name_);
  results.insert(results.end(), exact.begin(), exact.end());
  ctx.checks.insert(ctx.checks.end(), results.begin(), results.end());
}

}  // namespace choc
