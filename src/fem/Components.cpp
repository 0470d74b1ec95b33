// Component names and the parser of component lists ("DX DY", "dx,dz", "all", ...).
#include "fem/Components.hpp"

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace choc {

namespace {

const char* const kNames[kNumComponents] = {"DX", "DY", "DZ", "DRX", "DRY", "DRZ"};

std::string upper(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::toupper(static_cast<unsigned char>(ch)));
  return s;
}

std::string validNames() {
  std::string out;
  for (int c = 0; c < kNumComponents; ++c) out += std::string(kNames[c]) + ", ";
  return out + "ALL, TRANSLATIONS, ROTATIONS";
}

}  // namespace

const char* componentName(int c) {
  if (c < 0 || c >= kNumComponents) return "?";
  return kNames[c];
}

int componentFromName(const std::string& name) {
  const std::string u = upper(name);
  for (int c = 0; c < kNumComponents; ++c)
    if (u == kNames[c]) return c;
  return -1;
}

std::vector<int> parseComponents(const std::string& text) {
  std::vector<int> out;
  std::string token;
  auto flush = [&]() {
    if (token.empty()) return;
    const std::string u = upper(token);
    if (u == "ALL") {
      for (int c = 0; c < kNumComponents; ++c) out.push_back(c);
    } else if (u == "TRANSLATIONS") {
      out.insert(out.end(), {DX, DY, DZ});
    } else if (u == "ROTATIONS") {
      out.insert(out.end(), {DRX, DRY, DRZ});
    } else {
      const int c = componentFromName(u);
      if (c < 0)
        throw std::invalid_argument("unknown component '" + token + "' (valid: " +
                                    validNames() + ")");
      out.push_back(c);
    }
    token.clear();
  };
  for (char ch : text) {
    if (ch == ',' || std::isspace(static_cast<unsigned char>(ch)))
      flush();
    else
      token += ch;
  }
  flush();
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace choc
