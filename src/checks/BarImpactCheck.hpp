// Check 'Bar Impact Exact Solution': the history of point A (displacement, and velocity and
// contact force when recorded) against the d'Alembert solution of the two-bar impact
// (SDNL111, docs/verification/benchmarks.md) or, with 'Obstacle' = 'rigid wall', of a bar
// dropped on a rigid wall (SDNV100,
// at its contact end or its free end), with the wave speed and impedance from the material of A's block. Logs
// the max and RMS errors relative to the peak; gives checks.csv rows for the tolerances set.
#pragma once
#include "checks/HistoryCheck.hpp"

namespace choc {

Teuchos::ParameterList barImpactCheckParameters();
std::unique_ptr<HistoryCheck> makeBarImpactCheck(const Teuchos::ParameterList& row,
                                                 const Model& model, const CheckSite& site);

}  // namespace choc
