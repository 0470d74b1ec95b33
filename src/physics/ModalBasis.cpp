#include "physics/ModalBasis.hpp"

#include <cmath>

namespace choc {

double ModalBasis::frequencyHz(int mode) const {
  const double l = eigenvalues[mode];
  return l > 0 ? std::sqrt(l) / (2.0 * M_PI) : 0.0;
}

}  // namespace choc
