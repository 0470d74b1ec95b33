#include "fem/DofMap.hpp"

#include <algorithm>
#include <bitset>

namespace choc {

void DofMap::number(const std::vector<int>& order) {
  const int n = static_cast<int>(mask_.size());
  first_.assign(n, 0);
  pos_.assign(n, 0);
  long long next = 0;
  for (int p = 0; p < n; ++p) {
    pos_[order[p]] = p;
    first_[order[p]] = next;
    next += std::bitset<8>(mask_[order[p]]).count();
  }
  numGlobal_ = next;
}

DofMap::DofMap(std::vector<std::uint8_t> freeMask, int numRanks, int rank)
    : mask_(std::move(freeMask)) {
  const int n = static_cast<int>(mask_.size());
  std::vector<int> identity(n);
  for (int i = 0; i < n; ++i) identity[i] = i;
  number(identity);
  // Rank r owns the nodes whose first DOF lies in [r N / p, (r+1) N / p).
  std::vector<long long> firstAt(first_);
  rankNodeBegin_.assign(numRanks + 1, n);
  rankNodeBegin_[0] = 0;
  for (int r = 1; r < numRanks; ++r) {
    const long long target = numGlobal_ * r / numRanks;
    rankNodeBegin_[r] = static_cast<int>(std::lower_bound(firstAt.begin(), firstAt.end(), target) - firstAt.begin());
    rankNodeBegin_[r] = std::max(rankNodeBegin_[r], rankNodeBegin_[r - 1]);
  }
  nodeBegin_ = rankNodeBegin_[rank];
  nodeEnd_ = rankNodeBegin_[rank + 1];
  ownedBegin_ = nodeBegin_ < n ? first_[nodeBegin_] : numGlobal_;
  ownedEnd_ = nodeEnd_ < n ? first_[nodeEnd_] : numGlobal_;
}

DofMap::DofMap(std::vector<std::uint8_t> freeMask, const std::vector<int>& order,
               std::vector<int> rankBegin, int rank)
    : mask_(std::move(freeMask)), rankNodeBegin_(std::move(rankBegin)) {
  const int n = static_cast<int>(mask_.size());
  number(order);
  nodeBegin_ = rankNodeBegin_[rank];
  nodeEnd_ = rankNodeBegin_[rank + 1];
  ownedBegin_ = nodeBegin_ < n ? first_[order[nodeBegin_]] : numGlobal_;
  ownedEnd_ = nodeEnd_ < n ? first_[order[nodeEnd_]] : numGlobal_;
}

long long DofMap::dof(int node, int comp) const {
  const std::uint8_t m = mask_[node];
  if (!((m >> comp) & 1u)) return -1;
  return first_[node] + std::bitset<8>(m & ((1u << comp) - 1u)).count();
}

int DofMap::ownerOfNode(int node) const {
  auto it = std::upper_bound(rankNodeBegin_.begin(), rankNodeBegin_.end(), pos_[node]);
  return static_cast<int>(it - rankNodeBegin_.begin()) - 1;
}

std::vector<int> DofMap::order() const {
  std::vector<int> o(pos_.size());
  for (int node = 0; node < static_cast<int>(pos_.size()); ++node) o[pos_[node]] = node;
  return o;
}

}  // namespace choc
