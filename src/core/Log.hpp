// The run log: stdout on rank 0, nothing on the other ranks.
#pragma once
#include <ostream>

namespace choc {

std::ostream& log();
bool isRootRank();

}  // namespace choc
