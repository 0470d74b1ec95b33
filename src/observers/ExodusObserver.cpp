#include "observers/ExodusObserver.hpp"

#include <mpi.h>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include <cmath>

#include "core/Errors.hpp"
#include "core/Log.hpp"
#include "core/CollectiveFailure.hpp"
#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"

namespace choc {

ExodusObserver::ExodusObserver(const std::string& path, const Model& model,
                               const HistoryObserver& history, int interval,
                               const StateArchive* resume)
    : path_(path), model_(model), history_(history), interval_(interval), resume_(resume) {
  u_ = rcp(new Vector(model.map()));
  v_ = rcp(new Vector(model.map()));
  a_ = rcp(new Vector(model.map()));
}

void ExodusObserver::begin(TransientView& view) {
  std::string failure;
  try {
    if (isRootRank()) open(view);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  failure = collectiveFailure(*model_.comm(), failure);
  if (!failure.empty()) throw InputError(failure);
}

void ExodusObserver::archive(StateArchive& a) const {
  a.putInt("exodus/steps", exo_ ? exo_->stepsWritten() : 0);
  a.putDouble("exodus/time", exo_ ? exo_->lastTime() : 0.0);
}

void ExodusObserver::open(TransientView& view) {
  std::vector<std::string> nodal;
  for (const char* field : {"DISP_", "VEL_", "ACC_"})
    for (int c : spatialComponents(model_.mesh().dimension)) nodal.push_back(field + std::string(1, "XYZ"[c - DX]));
  std::vector<std::string> globals = {"KINETIC_ENERGY", "STRAIN_ENERGY", "CONTACT_ENERGY",
                                      "TOTAL_ENERGY"};
  if (const InteractionOutput* io = view.interactions()) {
    for (const auto& n : io->nodalFieldNames()) nodal.push_back(n);
    for (const auto& g : io->globalNames()) globals.push_back(g);
  }
  const ElementVariables element{view.elementFieldNames(), view.elementFieldBlocks()};
  if (resume_)
    exo_ = std::make_unique<ExodusResultsWriter>(
        path_, model_.mesh(), nodal, globals,
        ExodusResultsWriter::Resume{static_cast<int>(resume_->getInt("exodus/steps")),
                                    resume_->getDouble("exodus/time")},
        element);
  else
    exo_ = std::make_unique<ExodusResultsWriter>(path_, model_.mesh(), nodal, globals, element);
}

void ExodusObserver::step(TransientView& view) {
  const StepPoint pt = view.point();
  pending_ = pt.step % interval_ != 0 && !pt.last;
  if (!pending_) write(view);
}

void ExodusObserver::failed(TransientView& view) {
  if (!pending_) return;
  pending_ = false;
  view.fields(*u_, *v_, *a_);
  double finite = 1.0, all = 1.0;  // a state with a non-finite value is not written
  for (const Vector* x : {u_.get(), v_.get(), a_.get()})
    for (double value : x->getData()) finite = std::isfinite(value) ? finite : 0.0;
  Teuchos::reduceAll<int, double>(*model_.comm(), Teuchos::REDUCE_MIN, finite, Teuchos::outArg(all));
  if (all > 0) write(view);
}

void ExodusObserver::write(TransientView& view) {
  const StepPoint pt = view.point();
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
  // Element variables: each rank fills its elements, rank 0 receives the sum.
  std::vector<std::vector<double>> element;
  view.elementFields(element);
  for (auto& values : element) {
    if (model_.comm()->getSize() == 1) break;
    std::vector<double> sum(values.size(), 0.0);
    MPI_Reduce(values.data(), sum.data(), static_cast<int>(values.size()), MPI_DOUBLE, MPI_SUM, 0, model_.rawComm());
    values.swap(sum);
  }
  std::string failure;
  try {
    if (exo_) exo_->writeStep(pt.time, nodal, globals, element);
  } catch (const OutputError& e) {
    failure = e.what();
  }
  failure = collectiveFailure(*model_.comm(), failure);
  if (!failure.empty()) throw OutputError(failure);
}

void ExodusObserver::end(bool ok) {
  if (exo_ && ok) exo_->finish();
  if (exo_ && !ok) exo_->abandon();
}

}  // namespace choc
