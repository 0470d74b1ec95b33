// What a checkpoint must agree with before a run may continue from it: the input (every
// parameter, flattened to "path = value" lines, except those a restart may change: the
// restarted analysis's 'End Time', any 'Checkpoint' settings and 'Progress Interval') and the
// mesh (coordinates, blocks, sets). A mismatch names the first parameter that differs.
#pragma once
#include <cstdint>
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "mesh/Mesh.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

// "Analyses/c/Time Step = 1e-06" lines, in the list's order, without the restart-tolerant
// keys of analysis `analysis`.
std::string canonicalInput(const Teuchos::ParameterList& input, const std::string& analysis);
std::uint64_t meshHash(const Mesh& mesh);

struct RunIdentity {
  std::string analysis;  // the transient that wrote the checkpoint
  std::string input;     // canonicalInput
  std::uint64_t mesh = 0;
  int ranks = 1;
  void save(StateArchive& a) const;
  static RunIdentity load(const StateArchive& a);
  // "" when `other` (this run) may continue from this (the checkpoint's) identity; otherwise
  // what differs, e.g. "parameter 'Analyses/c/Time Step' is 2e-06 in the input, 1e-06 in the
  // checkpoint".
  std::string mismatch(const RunIdentity& other) const;
};

}  // namespace choc
