// libFuzzer target: the XML input reader and the validation of the top-level input.
// The input bytes are written to a file (readXmlParameters takes a path), read, then validated
// against topLevelParameters(). choc::InputError is the expected way to reject an input; any
// other exception escapes and libFuzzer reports it as a crash ("deadly signal": abort).
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "analysis/ModelInput.hpp"
#include "input/Errors.hpp"
#include "input/Validation.hpp"
#include "input/XmlInput.hpp"

namespace {
std::string tempPath() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/choc_fuzz_xml_" + std::to_string(getpid()) + ".xml";
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::string path = tempPath();
  static const Teuchos::ParameterList valid = choc::topLevelParameters();
  if (std::FILE* f = std::fopen(path.c_str(), "wb")) {
    std::fwrite(data, 1, size, f);
    std::fclose(f);
  } else {
    std::abort();
  }
  try {
    auto pl = choc::readXmlParameters(path);
    choc::validate(*pl, valid, choc::InputLocation{path, ""});
  } catch (const choc::InputError&) {
    // the expected rejection
  }
  return 0;
}
