// Writing a choc::Mesh to an Exodus II file (3 coordinates, block and set names).
#pragma once
#include <string>

#include "mesh/Mesh.hpp"

namespace choc {

// Longest block, set or variable name written to an Exodus file by choc.
constexpr int kExodusMaxNameLength = 64;

// Writes (overwrites) path. Throws std::runtime_error naming the path on an I/O failure,
// std::invalid_argument for a mesh that cannot be stored (name too long, duplicate ids,
// unknown topology). Entities with id <= 0 get the next free positive id.
// Files are netCDF 64-bit offset (CDF-2) unless `netcdf4` asks for netCDF-4 (HDF5) storage.
void writeExodusMesh(const Mesh& mesh, const std::string& path, bool netcdf4 = false);

// As writeExodusMesh, but leaves the file open and returns its Exodus id (the caller
// ex_close()s it): used by writers that add results to the mesh.
int createExodusMeshFile(const Mesh& mesh, const std::string& path, bool netcdf4 = false);

// "<what> failed for <path>: <Exodus error message>" after a failed ex_* call.
std::string exodusFailure(const std::string& what, const std::string& path);

}  // namespace choc
