// Check 'Impact': a statistic of the impacts of one shock link (observers/ImpactObserver.hpp)
// against a reference: a quantity of impact k (peak time, peak force, duration, impulse,
// impact velocity, ...) or, with 'Impact' = 0, of the whole run (number of impacts, largest
// peak force, ...). An impact that did not happen is NOOK, said in the note.
#pragma once
#include "checks/HistoryCheck.hpp"

namespace choc {

Teuchos::ParameterList impactCheckParameters();
std::unique_ptr<HistoryCheck> makeImpactCheck(const Teuchos::ParameterList& row, const Model& model,
                                              const CheckSite& site);

}  // namespace choc
