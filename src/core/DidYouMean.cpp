#include "core/DidYouMean.hpp"

#include <algorithm>
#include <cctype>

namespace choc {

namespace {

std::string lowered(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] != b[j - 1])});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

}  // namespace

std::string closestName(const std::string& key, const std::vector<std::string>& candidates) {
  std::string best;
  size_t bestDist = std::string::npos;
  const std::string k = lowered(key);
  for (const auto& c : candidates) {
    size_t d = editDistance(k, lowered(c));
    if (d < bestDist) {
      bestDist = d;
      best = c;
    }
  }
  // Only suggest a name that is reasonably close.
  if (best.empty() || bestDist > std::max<size_t>(3, best.size() / 2)) return "";
  return best;
}

std::string didYouMean(const std::string& key, const std::vector<std::string>& candidates) {
  const std::string near = closestName(key, candidates);
  return near.empty() ? std::string() : "did you mean '" + near + "'? ";
}

std::string joinNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s.empty() ? "(none)" : s;
}

std::string quotedNames(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "'" : ", '") + n + "'";
  return s;
}

}  // namespace choc
