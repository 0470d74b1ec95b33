// Agreeing on a failure that only some ranks saw (e.g. rank 0, which holds the gathered system
// of the direct solver): every rank must take the same branch, or the others wait forever in
// the next collective call.
#pragma once
#include <string>

#include "core/TpetraTypes.hpp"

namespace choc {

// Collective. `localFailure` is this rank's error message ("" if it saw none). Returns the
// message of the lowest failing rank on every rank, or "" when no rank failed.
std::string collectiveFailure(const Comm& comm, const std::string& localFailure);

}  // namespace choc
