// What a factored (or preconditioned) matrix was built from, compared in full before each
// solve, so that a stale factorisation cannot be reused: the scalar coefficients the matrix was
// combined with (W = ca M + cv C + cd K_T: ca, cv, cd), the version of the structural model's
// tangent (physics/InternalForce.hpp: it changes whenever the tangent's values do), and a
// status signature (contact statuses, the links' tangent key). A change of the status alone
// may keep the factorisation as a preconditioner of the changed matrix (the solver's update);
// any other change needs a new factorisation.
#pragma once
#include <utility>
#include <vector>

namespace choc {

struct FactorizationKey {
  std::vector<double> coefficients;
  long long tangent = 0;
  std::vector<char> status;
};

enum class KeyChange { None, StatusOnly, Matrix };

class FactorizationCache {
 public:
  KeyChange compare(const FactorizationKey& k) const {
    if (!valid_ || k.coefficients != key_.coefficients || k.tangent != key_.tangent) return KeyChange::Matrix;
    return k.status == key_.status ? KeyChange::None : KeyChange::StatusOnly;
  }
  void record(FactorizationKey k) {
    key_ = std::move(k);
    valid_ = true;
  }
  void forget() { valid_ = false; }  // the next solve factors again
  bool valid() const { return valid_; }
  const FactorizationKey& key() const { return key_; }

 private:
  FactorizationKey key_;
  bool valid_ = false;
};

}  // namespace choc
