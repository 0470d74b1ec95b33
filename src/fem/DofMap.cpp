#include "fem/DofMap.hpp"

#include <algorithm>
#include <bitset>

namespace choc {

DofMap::DofMap(std::vector<std::uint8_t> freeMask, int numRanks, int rank)
    : mask_(std::move(freeMask)) {
  const int n = static_cast<int>(mask_.size());
  first_.assign(n + 1, 0);
  for (int i = 0; i < n; ++i) first_[i + 1] = first_[i] + std::bitset<8>(mask_[i]).count();
  numGlobal_ = first_[n];
  // Rank r owns the nodes whose first DOF lies in [r N / p, (r+1) N / p).
  rankNodeBegin_.assign(numRanks + 1, n);
  rankNodeBegin_[0] = 0;
  for (int r = 1; r < numRanks; ++r) {
    const long long target = numGlobal_ * r / numRanks;
    rankNodeBegin_[r] =
        static_cast<int>(std::lower_bound(first_.begin(), first_.begin() + n, target) - first_.begin());
    rankNodeBegin_[r] = std::max(rankNodeBegin_[r], rankNodeBegin_[r - 1]);
  }
  nodeBegin_ = rankNodeBegin_[rank];
  nodeEnd_ = rankNodeBegin_[rank + 1];
  ownedBegin_ = first_[nodeBegin_];
  ownedEnd_ = first_[nodeEnd_];
}

long long DofMap::dof(int node, int comp) const {
  const std::uint8_t m = mask_[node];
  if (!((m >> comp) & 1u)) return -1;
  return first_[node] + std::bitset<8>(m & ((1u << comp) - 1u)).count();
}

int DofMap::ownerOfNode(int node) const {
  auto it = std::upper_bound(rankNodeBegin_.begin(), rankNodeBegin_.end(), node);
  return static_cast<int>(it - rankNodeBegin_.begin()) - 1;
}

}  // namespace choc
