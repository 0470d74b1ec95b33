// The energies of a recorded state and the work done since the start [J], as the structural
// operator accounts them (StructuralOperator::energies), and the work integrals it carries from
// one recorded state to the next (the trapezoidal rule on their power): the Rayleigh damping's
// dissipation, the moving rigid obstacles' work and the loads' work (LoadWork).
#pragma once
#include <vector>

#include "physics/Loads.hpp"

namespace choc {

struct StateEnergies {
  double kinetic = 0, strain = 0, contact = 0;  // contact: the penalty and stick springs, the links' springs
  double dissipated = 0;  // damping, links, friction and plastic work
  double external = 0;    // the loads' and the moving obstacles' work
  double plastic = 0;     // the plastic work (a part of dissipated)
  double hourglass = 0;   // the one-point elements' hourglass energy (a part of strain)
  double shadow = 0;      // explicit sub-steps: (h^2/8) a^T M a (observers/TransientView.hpp, EnergyTerms)
};

struct WorkIntegrals {
  explicit WorkIntegrals(const Loads* loads) : loadWork(loads) {}
  LoadWork loadWork;
  double damping = 0.0, lastDampingPower = 0.0;
  double obstacles = 0.0, lastObstaclePower = 0.0;
  double velocityUpdate = 0.0;  // the kinetic energy the contact velocity update took [J]
  // For a checkpoint (with loadWork's own state), and back.
  std::vector<double> state() const { return {damping, lastDampingPower, obstacles, lastObstaclePower}; }
  void restore(const std::vector<double>& s) {
    damping = s[0];
    lastDampingPower = s[1];
    obstacles = s[2];
    lastObstaclePower = s[3];
  }
};

}  // namespace choc
