// A check of a netCDF file's header before the netCDF library parses it.
//
// The library trusts the counts and lengths a classic header declares: a corrupted count or
// name length makes it allocate gigabytes or loop for minutes before it fails. Walking the
// header first, with every count checked against the bytes the file actually holds, turns
// such a file into one clear InputError.
#pragma once
#include <string>

namespace choc {

// The storage of an Exodus II file, told by its first bytes.
enum class NetcdfStorage {
  Classic,  // netCDF classic: CDF-1, CDF-2 (64-bit offset) or CDF-5 (64-bit data)
  Hdf5,     // netCDF-4: an HDF5 signature at offset 0, 512, 1024, 2048, ...
  Unknown,  // neither (empty, text, another format)
};

// Reads the signature of the file at `path` and, for a classic file, walks its header (see
// the netCDF file format specification): every list, name and attribute must fit in the file,
// names are 1 to 256 bytes, types are known, dimension ids are in range with the record
// dimension only first, and every variable's data lies inside the file (a truncated file is
// caught here). Throws choc::InputError naming the path and the byte offset of the first
// inconsistency. An HDF5 file is left to the library. Unknown is returned, not thrown, so the
// caller words that message.
NetcdfStorage checkNetcdfHeader(const std::string& path);

}  // namespace choc
