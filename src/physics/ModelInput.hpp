// The valid top-level input: Title, Mesh, Model (materials, blocks, Dirichlet conditions,
// active components) and Analyses (each validated by its own type, see AnalysisRegistry).
#pragma once
#include <Teuchos_ParameterList.hpp>

namespace choc {

Teuchos::ParameterList topLevelParameters();

}  // namespace choc
