// The nodal quantities an analysis records in its history, parsed from the
// 'History' parameter ("A:DX A:VX N1:DZ ..."): <node set>:<quantity>, quantity one of
// DX DY DZ DRX DRY DRZ (displacement), VX VY VZ (velocity), AX AY AZ (acceleration).
// A node set with several nodes is probed at its first node.
#pragma once
#include <string>
#include <vector>

#include "physics/Model.hpp"

namespace choc {

enum class ProbeField { Displacement = 0, Velocity = 1, Acceleration = 2 };

struct Probe {
  std::string column;  // "A:DX"
  int node = -1;
  int component = 0;   // DX..DRZ
  ProbeField field = ProbeField::Displacement;
  long long dof = -1;  // -1: the component is fixed (the value is 0)
};

// Throws InputError naming `parameter` for a malformed entry or an unknown node set.
std::vector<Probe> parseProbes(const std::string& text, const Model& model,
                               const std::string& parameter);

}  // namespace choc
