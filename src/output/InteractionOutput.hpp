// What a set of interactions (the contact pairs of a direct transient, the shock links of a
// modal transient) reports at a recorded state: history columns, Exodus nodal and global
// variables, and a note for the progress line. Implemented by the owner of the interactions
// (contact/ContactReport, physics/ModalLinks), read by the output observers.
#pragma once
#include <string>
#include <vector>

namespace choc {

class InteractionOutput {
 public:
  virtual ~InteractionOutput() = default;
  // '<name>:force', '<name>:gap'...: the same list at every step.
  virtual std::vector<std::string> historyColumns() const = 0;
  virtual std::vector<double> historyValues() const = 0;
  // Nodal Exodus variables: names, and values[variable][mesh node].
  virtual std::vector<std::string> nodalFieldNames() const { return {}; }
  virtual std::vector<std::vector<double>> nodalFields() const { return {}; }
  virtual std::vector<std::string> globalNames() const = 0;
  virtual std::vector<double> globalValues() const = 0;
  // A few words for the progress line, e.g. "12 active".
  virtual std::string progressNote() const = 0;
};

}  // namespace choc
