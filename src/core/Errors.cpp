#include "core/Errors.hpp"

namespace choc {

std::string inputMessage(const std::string& file, const std::string& parameter,
                         const std::string& value, const std::string& problem,
                         const std::string& fix) {
  std::string m = file.empty() ? std::string("input") : file;
  m += ": ";
  if (!parameter.empty()) {
    m += "parameter '" + parameter + "'";
    if (!value.empty()) m += " = '" + value + "'";
    m += ": ";
  }
  m += problem;
  if (!fix.empty()) m += "; " + fix;
  // One line, always.
  for (char& c : m)
    if (c == '\n' || c == '\r') c = ' ';
  return m;
}

void throwInput(const std::string& file, const std::string& parameter, const std::string& value,
                const std::string& problem, const std::string& fix) {
  throw InputError(inputMessage(file, parameter, value, problem, fix));
}

}  // namespace choc
