// Reading a mesh file by its kind: gmsh (.msh) or Exodus II (anything else: .exo, .e, .g...).
#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace choc {

bool isGmshFile(const std::string& path);
Mesh readMeshFile(const std::string& path);

}  // namespace choc
