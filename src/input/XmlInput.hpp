// Reading a Teuchos XML parameter list from a file, with one-line errors.
#pragma once
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace choc {

// Throws InputError naming the file when it is missing, unreadable, empty or not valid XML
// for a Teuchos parameter list.
Teuchos::RCP<Teuchos::ParameterList> readXmlParameters(const std::string& path);

// Resolves `relative` against the directory of `inputFile` (absolute paths pass through).
std::string resolveBeside(const std::string& inputFile, const std::string& relative);

}  // namespace choc
