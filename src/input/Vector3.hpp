// Reading a three-component vector written as "x y z" in a string parameter.
#pragma once
#include <array>
#include <string>

namespace choc {

// Throws InputError naming file and parameter unless `text` holds exactly three numbers.
std::array<double, 3> parseVector3(const std::string& text, const std::string& file,
                                   const std::string& parameter);

}  // namespace choc
