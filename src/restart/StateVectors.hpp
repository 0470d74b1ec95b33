// Distributed vectors in a checkpoint, independent of the ranks and the partition that wrote
// them: stored in the mesh's node order (node-major, the free components of each node), so a
// run on 2 ranks (or with a Zoltan2 partition) restarts from a 1-rank checkpoint and back.
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/DofMap.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

class StateVectors {
 public:
  explicit StateVectors(const DofMap& dofs);
  // Collective (a gather); every rank stores the same record.
  void put(StateArchive& a, const std::string& name, const Vector& v) const;
  // Fills the owned entries of v. Throws StateRecordError when the record has the wrong size.
  void get(const StateArchive& a, const std::string& name, Vector& v) const;

 private:
  const DofMap& dofs_;
  std::vector<long long> canonicalDof_;  // global DOF of each canonical position
};

}  // namespace choc
