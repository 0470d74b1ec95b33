#include "observers/ExodusObserver.hpp"

#include <Tpetra_Vector.hpp>

#include "core/Log.hpp"
#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"

namespace choc {

ExodusObserver::ExodusObserver(const std::string& path, const Model& model,
                               const HistoryObserver& history, int interval)
    : path_(path), model_(model), history_(history), interval_(interval) {
  u_ = rcp(new Vector(model.map()));
  v_ = rcp(new Vector(model.map()));
  a_ = rcp(new Vector(model.map()));
}

void ExodusObserver::begin(TransientView& view) {
  if (!isRootRank()) return;
  std::vector<std::string> nodal;
  for (const char* field : {"DISP_", "VEL_", "ACC_"})
    for (int c : spatialComponents(model_.mesh().dimension)) nodal.push_back(field + std::string(1, "XYZ"[c - DX]));
  std::vector<std::string> globals = {"KINETIC_ENERGY", "STRAIN_ENERGY", "CONTACT_ENERGY",
                                      "TOTAL_ENERGY"};
  if (const InteractionOutput* io = view.interactions()) {
    for (const auto& n : io->nodalFieldNames()) nodal.push_back(n);
    for (const auto& g : io->globalNames()) globals.push_back(g);
  }
  exo_ = std::make_unique<ExodusResultsWriter>(path_, model_.mesh(), nodal, globals);
}

void ExodusObserver::step(TransientView& view) {
  const StepPoint pt = view.point();
  if (pt.step % interval_ != 0 && !pt.last) return;
  view.fields(*u_, *v_, *a_);
  const DofMap& dofs = model_.dofs();
  const auto U = gatherAll(*u_, 0, dofs), V = gatherAll(*v_, 0, dofs), A = gatherAll(*a_, 0, dofs);
  const InteractionOutput* io = view.interactions();
  std::vector<std::vector<double>> nodal;
  for (const auto* X : {&U, &V, &A})
    for (int c : spatialComponents(model_.mesh().dimension)) nodal.push_back(nodalComponent(*X, dofs, c));
  const EnergyTerms& e = history_.lastEnergies();
  std::vector<double> globals = {e.kinetic, e.strain, e.contact, e.total()};
  if (io) {
    for (auto& f : io->nodalFields()) nodal.push_back(std::move(f));
    for (double g : io->globalValues()) globals.push_back(g);
  }
  if (exo_) exo_->writeStep(pt.time, nodal, globals);
}

void ExodusObserver::end(bool ok) {
  if (exo_ && ok) exo_->finish();
  if (exo_ && !ok) exo_->abandon();
}

}  // namespace choc
