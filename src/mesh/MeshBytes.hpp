// A Mesh as bytes and back: how a mesh read in a child process (ChildProcess.hpp) reaches
// the parent.
#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace choc {

std::string meshToBytes(const Mesh& mesh);
// Throws std::runtime_error on bytes that meshToBytes did not write whole.
Mesh meshFromBytes(const std::string& bytes);

}  // namespace choc
