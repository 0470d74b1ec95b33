// Products A x of the last x they were computed for: a later request at the same x (equal on
// every rank, entry by entry) reuses them instead of streaming a matrix again. The energy
// output asks for K u, K v and M v of the state a step ended at, which the step's last residual
// has just computed. Several products can share one x (K v and M v): one copy of the key.
#pragma once
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

class ProductCache {
 public:
  ProductCache(RCP<const Map> map, int products);
  // A new entry for x (copied as its key); no product is held until written.
  void reset(const Vector& x);
  // Product i's buffer, to be written by the caller (nothing is copied); it is held from now.
  Vector& write(int i);
  // Collective: true when product i is held for this x (on every rank).
  bool holds(const Vector& x, int i) const;
  const Vector& product(int i) const { return *Ax_[size_t(i)]; }

 private:
  RCP<Vector> x_;
  std::vector<RCP<Vector>> Ax_;
  std::vector<char> held_;
};

}  // namespace choc
