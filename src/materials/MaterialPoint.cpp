// What every material point shares (MaterialPoint.hpp).
#include "materials/MaterialPoint.hpp"

namespace choc {

Mat3 cauchyFromFirstPiola(const Mat3& P, const Mat3& F, bool finiteStrain) {
  if (!finiteStrain) return P;
  Mat3 c = multiply(P, transpose(F));
  const double J = determinant(F);
  for (auto& row : c)
    for (double& v : row) v /= J;
  return c;
}

}  // namespace choc
