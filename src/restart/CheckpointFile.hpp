// Checkpoint files: a StateArchive behind a magic line, its length and an FNV-1a checksum.
// Written atomically: "<path>.tmp", flushed and fsync'ed, renamed over <path>, then the
// directory fsync'ed, so a kill at any moment leaves either the previous checkpoint or the new
// one, never a mixture.
#pragma once
#include <string>

#include "restart/StateArchive.hpp"

namespace choc {

// Throws OutputError naming the file when it cannot be written (disk full, file-size limit);
// the previous checkpoint at <path> is then left as it was.
void writeCheckpointFile(const std::string& path, const StateArchive& archive);

// Throws InputError naming the file when it is missing, truncated, corrupt (checksum) or not
// a checkpoint.
StateArchive readCheckpointFile(const std::string& path);

}  // namespace choc
