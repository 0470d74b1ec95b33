// What a set of interactions (the contact pairs of a direct transient, the shock links of a
// modal transient) reports at a recorded state: history columns, Exodus nodal and global
// variables, and a note for the progress line. Implemented by the owner of the interactions
// (contact/ContactReport, physics/ModalLinks), read by the output observers.
#pragma once
#include <string>
#include <vector>

namespace choc {

// One interaction's state for the impact statistics: normal force (>= 0), gap, gap rate
// d(gap)/dt (negative when closing; NaN: the statistics difference successive gaps), tangential
// force and slip speed.
struct ImpactSample {
  double force = 0, gap = 0, gapRate = 0, tangentialForce = 0, slipSpeed = 0;
};

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
  // The interactions whose impacts are counted (names) and their samples at this state.
  virtual std::vector<std::string> impactNames() const { return {}; }
  virtual std::vector<ImpactSample> impactSamples() const { return {}; }
};

}  // namespace choc
