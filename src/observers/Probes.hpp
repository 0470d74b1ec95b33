// The quantities an analysis records in its history, parsed from the 'History' parameter
// ("A:DX A:VX N1:DZ BODY:LZ ..."): <node set>:<quantity>, quantity one of
// DX DY DZ DRX DRY DRZ (displacement), VX VY VZ (velocity), AX AY AZ (acceleration): a node set
// with several nodes is probed at its first node; or, for the direct transient, the whole set's
// PX PY PZ (linear momentum) and LX LY LZ (angular momentum about its centre of mass),
// observers/SetMomentum.hpp.
#pragma once
#include <array>
#include <string>
#include <vector>

#include "core/Vec3.hpp"
#include "physics/Model.hpp"

namespace choc {

enum class ProbeField { Displacement = 0, Velocity = 1, Acceleration = 2, Momentum = 3, AngularMomentum = 4 };

struct Probe {
  std::string column;  // "A:DX"
  int node = -1;
  int component = 0;   // DX..DRZ
  ProbeField field = ProbeField::Displacement;
  long long dof = -1;  // -1: the component is fixed (the value is 0)
  // Momentum and AngularMomentum: the set's nodes, their coordinates and DOFs (-1: fixed).
  std::vector<Point3> X;
  std::vector<std::array<long long, 3>> dofs;
};

// Throws InputError naming `parameter` for a malformed entry or an unknown node set; momenta
// (PX ... LZ) only where `momenta` (the direct transient), in 3D and plane strain, on sets
// without rotation DOFs.
std::vector<Probe> parseProbes(const std::string& text, const Model& model, const std::string& parameter,
                               bool momenta = false);

}  // namespace choc
