// Suggestions for a misspelt name: the closest valid name by edit distance, and the text every
// "unknown name" message uses ("did you mean 'X'? ").
#pragma once
#include <string>
#include <vector>

namespace choc {

// The candidate closest to `key` by edit distance (case-insensitive); "" when none is close.
std::string closestName(const std::string& key, const std::vector<std::string>& candidates);

// "did you mean '<closest>'? " or "" when no candidate is close.
std::string didYouMean(const std::string& key, const std::vector<std::string>& candidates);

// "a, b, c" ("(none)" for an empty list).
std::string joinNames(const std::vector<std::string>& names);

// "'a', 'b', 'c'".
std::string quotedNames(const std::vector<std::string>& names);

}  // namespace choc
