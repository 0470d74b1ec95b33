// Reading and validating a whole input: the top-level keys, then every analysis by its type.
#pragma once
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace choc {

Teuchos::RCP<Teuchos::ParameterList> readAndValidateInput(const std::string& path);

}  // namespace choc
