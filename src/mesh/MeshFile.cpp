#include "mesh/MeshFile.hpp"

#include <algorithm>
#include <cctype>

#include "mesh/ExodusReader.hpp"
#include "mesh/GmshReader.hpp"

namespace choc {

bool isGmshFile(const std::string& path) {
  const auto dot = path.rfind('.');
  if (dot == std::string::npos) return false;
  std::string ext = path.substr(dot + 1);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == "msh";
}

Mesh readMeshFile(const std::string& path) {
  return isGmshFile(path) ? readGmshMesh(path) : readExodusMesh(path);
}

}  // namespace choc
