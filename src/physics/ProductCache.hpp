// The last product A x computed with one matrix and that x: a later request for A x at the
// same x (equal on every rank, entry by entry) reuses it instead of streaming A again. The
// energy output asks for K u, K v and M v of the state a step ended at, which the step's last
// residual has just computed.
#pragma once
#include "core/TpetraTypes.hpp"

namespace choc {

class ProductCache {
 public:
  explicit ProductCache(RCP<const Map> map);
  void store(const Vector& x, const Vector& Ax);
  // Collective: true when the stored x equals x on every rank.
  bool holds(const Vector& x) const;
  const Vector& product() const { return *Ax_; }
  void clear() { valid_ = false; }

 private:
  RCP<Vector> x_, Ax_;
  bool valid_ = false;
};

}  // namespace choc
