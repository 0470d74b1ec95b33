// The active-set state of the contact constraints, one layer of contact (beside the geometry:
// pairing, obstacles, followed surfaces; the constraint rows and gaps; the friction law; the
// explicit forward increments): per constraint its status (1: in contact) and pressure
// lambda_s [N, compression positive], the copies of the last accepted step (save at
// acceptance, restore when a step is cut or fails), the scale of the multiplier rows, and a
// version bumped whenever a status changes; and its checkpoint records ("contact/status",
// "contact/pressure", "contact/scale": the accepted state).
#pragma once
#include <cstddef>
#include <vector>

#include "restart/StateArchive.hpp"

namespace choc {

struct ContactActiveSet {
  std::vector<char> status, savedStatus;
  std::vector<double> lambda, savedLambda;
  std::vector<double> lastCorrection;  // the last applyCorrection's change of lambda
  double scale = 1.0;
  int version = 0;

  void commit() {
    savedStatus = status;
    savedLambda = lambda;
  }
  void revert() {
    if (status != savedStatus) ++version;
    status = savedStatus;
    lambda = savedLambda;
  }
  int activeCount() const;
  // Right-hand side of constraint row s at its gap (force units): active -scale g_s, else lambda_s.
  double rowResidual(size_t s, double gap) const { return status[s] ? -scale * gap : lambda[s]; }
  // lambda += scale * dScaled (the multiplier unknowns are lambda / scale).
  void applyCorrection(const std::vector<double>& dScaled);
  // The last correction's change of lambda scaled by `factor` (a line search shortening it).
  void scaleLastCorrection(double factor);
  void archive(StateArchive& a) const;
  // The records of n constraints; the caller bumps the version and saves once it has restored
  // the rest of its state.
  void restore(const StateArchive& a, size_t n);
};

}  // namespace choc
