// Check 'Value': a history column at a time against a reference value with a relative or
// absolute tolerance (the document's table rows).
#pragma once
#include "checks/HistoryCheck.hpp"

namespace choc {

Teuchos::ParameterList valueCheckParameters();
std::unique_ptr<HistoryCheck> makeValueCheck(const Teuchos::ParameterList& row, const Model& model,
                                             const CheckSite& site);

}  // namespace choc
