// libFuzzer target: the XML input reader and the validation of the top-level input.
// The input bytes are written to a file (readXmlParameters takes a path), read, then validated
// against topLevelParameters(). choc::InputError is the expected way to reject an input; any
// other exception escapes and libFuzzer reports it as a crash ("deadly signal": abort).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "physics/ModelInput.hpp"
#include "fuzz_input_file.hpp"
#include "core/Errors.hpp"
#include "input/Validation.hpp"
#include "input/XmlInput.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const Teuchos::ParameterList valid = choc::topLevelParameters();
  const std::string& path = writeFuzzInput(data, size, "xml", "xml");
  try {
    auto pl = choc::readXmlParameters(path);
    choc::validate(*pl, valid, choc::InputLocation{path, ""});
  } catch (const choc::InputError&) {
    // the expected rejection
  }
  return 0;
}
