#include "input/OutputName.hpp"

#include <cstdio>

#include "core/Errors.hpp"

namespace choc {

namespace {

bool allowed(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
         c == '-' || c == '.';
}

// A character as the message shows it: printable ones quoted, the others by their code.
std::string shown(char c) {
  const auto u = static_cast<unsigned char>(c);
  if (u >= 0x20 && u < 0x7f) return std::string("'") + c + "'";
  char buf[16];
  std::snprintf(buf, sizeof buf, "byte 0x%02x", u);
  return buf;
}

}  // namespace

std::string outputNameRule() {
  return "use 1 to " + std::to_string(kMaxOutputNameLength) +
         " characters among letters, digits, '_', '-' and '.', starting with a letter, a digit or '_'";
}

std::string outputNameProblem(const std::string& name) {
  if (name.empty()) return "is empty";
  if (name.size() > kMaxOutputNameLength)
    return "is " + std::to_string(name.size()) + " characters long (names become file names and result columns)";
  for (char c : name)
    if (!allowed(c)) return "contains " + shown(c) + " (names become file names and result columns)";
  if (name[0] == '.' || name[0] == '-') return "starts with " + shown(name[0]);
  return "";
}

void checkOutputName(const std::string& file, const std::string& parameter, const std::string& name) {
  const std::string problem = outputNameProblem(name);
  if (problem.empty()) return;
  std::string value;  // the name as the message shows it: no control character
  for (char c : name) value += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
  if (value.size() > 48) value = value.substr(0, 45) + "...";
  throwInput(file, parameter, value, "the name " + problem, outputNameRule());
}

}  // namespace choc
