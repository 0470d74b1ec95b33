#include "input/Vector3.hpp"

#include <sstream>

#include "core/Errors.hpp"

namespace choc {

std::array<double, 3> parseVector3(const std::string& text, const std::string& file,
                                   const std::string& parameter) {
  std::istringstream in(text);
  std::array<double, 3> v{};
  for (double& x : v)
    if (!(in >> x)) throwInput(file, parameter, text, "expects three numbers 'x y z'");
  std::string rest;
  if (in >> rest) throwInput(file, parameter, text, "expects three numbers 'x y z'");
  return v;
}

}  // namespace choc
