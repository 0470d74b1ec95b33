// Names that become file names or result columns: an analysis ("<name>.exo",
// "<name>.history.csv"), a contact pair or a shock link ("<name>:force", "<name>_FORCE").
// One rule for all of them, checked by `choc check` as by `choc run`, so that no name can
// reach outside the output directory, break a CSV row or overflow an Exodus name.
#pragma once
#include <string>

namespace choc {

constexpr std::size_t kMaxOutputNameLength = 32;

// "" when `name` follows the rule, else what is wrong with it ("contains '/'", ...).
std::string outputNameProblem(const std::string& name);
// The rule in words, for the fix part of an error message.
std::string outputNameRule();
// Throws InputError naming the parameter when `name` breaks the rule.
void checkOutputName(const std::string& file, const std::string& parameter, const std::string& name);

}  // namespace choc
