// libFuzzer target: the Exodus II mesh reader. The bytes are written to a file
// (readExodusMesh takes a path). choc::InputError is the expected rejection; any other
// exception escapes and is reported as a crash. A mesh that is read is checked for
// consistency (connectivity and node sets within the node range).
#include <cstdint>
#include <cstdlib>
#include <string>

#include "fuzz_input_file.hpp"
#include "core/Errors.hpp"
#include "mesh/ExodusReader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string& path = writeFuzzInput(data, size, "exo", "exo");
  try {
    choc::Mesh mesh = choc::readExodusMesh(path);
    // The reader promises indices in range (ExodusReader.hpp): a violation is a finding.
    const int n = mesh.numNodes();
    for (const auto& b : mesh.blocks)
      for (int c : b.connectivity)
        if (c < 0 || c >= n) std::abort();
    for (const auto& s : mesh.nodeSets)
      for (int c : s.nodes)
        if (c < 0 || c >= n) std::abort();
  } catch (const choc::InputError&) {
    // the expected rejection
  }
  return 0;
}
