// One entry of a tangent added to the effective matrix (global row and column).
#pragma once
#include "core/TpetraTypes.hpp"

namespace choc {

struct MatrixEntry {
  GO row = 0, col = 0;
  double value = 0.0;
};

}  // namespace choc
