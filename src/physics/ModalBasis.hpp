// A modal basis: the mass-normalised modes a Modal analysis computed, kept for the modal
// transients of the same input.
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

struct ModalBasis {
  std::string name;
  std::vector<double> eigenvalues;  // omega^2, ascending
  RCP<const MultiVector> vectors;   // M-normalised mode shapes on the model's map
  double frequencyHz(int mode) const;
};

}  // namespace choc
