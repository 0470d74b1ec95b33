// Reading a Teuchos XML parameter list from a file, with one-line errors.
#pragma once
#include <string>

#include <Teuchos_ParameterList.hpp>
#include <Teuchos_RCP.hpp>

namespace choc {

// Throws InputError naming the file when it is missing, unreadable, empty or not valid XML
// for a Teuchos parameter list.
Teuchos::RCP<Teuchos::ParameterList> readXmlParameters(const std::string& path);

// A whole token as a decimal number (as the input's scalars are read): false for a
// hexadecimal float ("0x10", which strtod would read as 16), trailing characters or an empty
// token. Lists of numbers inside a string parameter use it too.
bool parseDecimal(const std::string& token, double& value);

// Resolves `relative` against the directory of `inputFile` (absolute paths pass through).
std::string resolveBeside(const std::string& inputFile, const std::string& relative);

}  // namespace choc
