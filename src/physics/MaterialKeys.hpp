// Which keys of Model/Materials/<name> each material law reads. A key the user gave that the
// chosen law does not read is an input error (an elastic answer where plasticity was asked for
// must not look right), and a key a law requires that was left out is reported as missing.
#pragma once
#include <string>

#include <Teuchos_ParameterList.hpp>

namespace choc {

// Throws InputError naming `file`, the key, the law and the law that would read it.
void checkMaterialKeys(const std::string& file, const std::string& materialName, const Teuchos::ParameterList& mp);

}  // namespace choc
