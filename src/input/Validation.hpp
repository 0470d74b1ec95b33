// Checking a user's parameter list against the valid list its owner declared.
#pragma once
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "core/DidYouMean.hpp"

namespace choc {

// Where a sublist came from, for error messages: the input file and the path of the sublist.
struct InputLocation {
  std::string file;
  std::string path;  // "" for the top level, else "Analyses/modes"
  InputLocation child(const std::string& name) const {
    return {file, path.empty() ? name : path + "/" + name};
  }
  std::string parameter(const std::string& name) const {
    return path.empty() ? name : path + "/" + name;
  }
};

// Validates `user` against `valid` and fills in defaults. Throws InputError (one line) on an
// unknown key (naming the closest valid key), a wrong type, a value out of range, a choice
// not offered, or a missing required key. Integers are accepted where a double is expected.
void validate(Teuchos::ParameterList& user, const Teuchos::ParameterList& valid,
              const InputLocation& where);

// Prints every parameter of `valid` with type, default and documentation, indented.
void printValidParameters(std::ostream& out, const Teuchos::ParameterList& valid,
                          const std::string& indent = "");

// Prints `valid` as markdown, depth first: a section "### `path`" (path "" is the top level)
// holding `doc` and a table of its keys (key, type, default or "required", valid values,
// documentation), then one section per sublist; a named sublist's section is its template
// ("path/<any name>"). Open sublists get a row only: their owner prints their sections.
void printValidParametersMarkdown(std::ostream& out, const Teuchos::ParameterList& valid,
                                  const std::string& path, const std::string& doc);

// Value of a parameter as text for messages.
std::string entryToString(const Teuchos::ParameterEntry& entry);

}  // namespace choc
