// What a transient analysis shows its output observers at a recorded state (the initial
// state and every accepted step). The direct and the modal transient each implement it; the
// observers (history, Exodus, progress, interrupt) are shared and know neither.
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "output/InteractionOutput.hpp"
#include "physics/StateEnergies.hpp"

namespace choc {

struct StepPoint {
  long long step = 0;  // 0: the initial state
  double time = 0.0;
  double dt = 0.0;     // of the step just taken (0 for the initial state)
  bool last = false;   // the final state of the run
  bool boundary = true;    // a state a checkpoint may hold (not a sub-step of a cut step)
  long long nominal = 0;   // nominal steps completed (the step index without cuts)
};

// Energies of the state [J] (physics/StateEnergies.hpp: dissipated and external are the work
// done since the start, plastic a part of dissipated, hourglass a part of strain). Explicit
// schemes (central differences, symplectic Euler) give shadow = (h^2/8) a^T M a, h the sub-step:
// velocity Verlet conserves E_total - shadow exactly on a linear system (E_total itself, measured
// with the integer-step velocity, swings by up to r^2 / (1 - r^2) of the energy at omega_max,
// r = h omega_max / 2): the energy balance measures that conserved energy.
struct EnergyTerms : StateEnergies {
  EnergyTerms() = default;
  explicit EnergyTerms(const StateEnergies& e) : StateEnergies(e) {}
  double total() const { return kinetic + strain + contact; }
};

class TransientView {
 public:
  virtual ~TransientView() = default;
  virtual StepPoint point() const = 0;
  // The probes' values (history columns before the energies), the same on every rank.
  virtual std::vector<double> probeValues() const = 0;
  // Called once per recorded state, in time order (integrates the damping work).
  virtual EnergyTerms energies() = 0;
  virtual const InteractionOutput* interactions() const = 0;  // null: none
  // Displacement, velocity and acceleration on the model's map (collective).
  virtual void fields(Vector& u, Vector& v, Vector& a) const = 0;
  // Element variables (names, the blocks carrying them, values[v][e] over the mesh's elements
  // with this rank's filled: InternalForce::elementFields); none by default. Collective.
  virtual std::vector<std::string> elementFieldNames() const { return {}; }
  virtual std::vector<char> elementFieldBlocks() const { return {}; }
  virtual void elementFields(std::vector<std::vector<double>>& /*values*/) const {}
  // Solver figures of the last step for the progress line ("" when none).
  virtual std::string stepNote() const = 0;
};

}  // namespace choc
