// Reading an Exodus II mesh file into a choc::Mesh.
#pragma once
#include <string>

#include "mesh/Mesh.hpp"
#include "mesh/Topology.hpp"

namespace choc {

// Reads coordinates (padded to 3 components), element blocks (BEAM2 and HEX8 topologies,
// canonicalised), node sets and side sets with their names. Unnamed entities are called
// "block_<id>", "nodeset_<id>", "sideset_<id>". A block with 0 elements is accepted
// whatever its type (Exodus stores it as "NULL"): it then has topology "" and 0 nodes. Any
// problem with the file (missing, not Exodus, truncated, corrupt, unsupported topology, indices
// out of range, a crash of the libraries reading it) throws choc::InputError with a one-line
// message naming the path. The Exodus, netCDF and HDF5 libraries read the file in a child
// process (ChildProcess.hpp); this process only runs choc's header check (NetcdfHeader.hpp).
Mesh readExodusMesh(const std::string& path);


}  // namespace choc
