#include "contact/ContactActiveSet.hpp"

#include <algorithm>

namespace choc {

int ContactActiveSet::activeCount() const { return static_cast<int>(std::count(status.begin(), status.end(), 1)); }

void ContactActiveSet::applyCorrection(const std::vector<double>& d) {
  lastCorrection.assign(lambda.size(), 0.0);
  for (size_t s = 0; s < lambda.size(); ++s) {
    lastCorrection[s] = scale * d[s];
    lambda[s] += lastCorrection[s];
  }
}

void ContactActiveSet::scaleLastCorrection(double factor) {
  for (size_t s = 0; s < lastCorrection.size() && s < lambda.size(); ++s) {
    lambda[s] += (factor - 1.0) * lastCorrection[s];
    lastCorrection[s] *= factor;
  }
}

void ContactActiveSet::archive(StateArchive& a) const {
  a.putVector("contact/status", savedStatus);
  a.putVector("contact/pressure", savedLambda);
  a.putDouble("contact/scale", scale);
}

void ContactActiveSet::restore(const StateArchive& a, size_t n) {
  status = a.getVector<char>("contact/status", n);
  lambda = a.getVector<double>("contact/pressure", n);
  scale = a.getDouble("contact/scale");
}

}  // namespace choc
