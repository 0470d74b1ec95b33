// Explicit integration of the generalized (modal) system
//   q'' + c o q' + w2 o q = f(t, q, q')        (c = 2 xi omega, w2 = omega^2, per mode)
// with a nonlinear generalized force f from the shock links. Schemes:
//   SymplecticEuler: a_n = f_n - c v_n - w2 q_n; v+ = v + dt a_n; q+ = q + dt v+;
//                    f_{n+1} = f(q+, v+)   (the reference deck's "Euler" scheme)
//   CentralDifference: velocity-Verlet form, modal damping implicit (exact for diagonal c),
//                      link forces at (q_{n+1}, v_{n+1/2})
//   Adaptive: central differences, each step cut into `refinement` sub-steps while a link is
//             closed or could close within the step (refines around shocks)
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "restart/StateArchive.hpp"

namespace choc {

class ModalForce {
 public:
  virtual ~ModalForce() = default;
  // Generalized force at (t, q, v); advances the links' internal state (one call per step).
  virtual void evaluate(double t, const std::vector<double>& q, const std::vector<double>& v,
                        double dt, std::vector<double>& f) = 0;
  // True when a link is closed or may close within `dt` of the last evaluated state.
  virtual bool nearContact(double dt) const = 0;
  // Constraints enforced by forward-increment Lagrange multipliers: called after the position
  // update of a step of length h with the predicted q (and the velocity that produced it);
  // applies the constraint impulses to both (q += h^2 B^T lambda, v += h B^T lambda).
  virtual void project(double /*h*/, std::vector<double>& /*q*/, std::vector<double>& /*v*/) {}
  // Generalized constraint force B^T lambda of the last project() (nullptr: no constraints).
  virtual const std::vector<double>* constraintForce() const { return nullptr; }
  // What the force carries between steps, for a checkpoint, and back.
  virtual void archive(StateArchive& /*a*/) const {}
  virtual void restore(const StateArchive& /*a*/) {}
};

enum class ModalScheme { SymplecticEuler, CentralDifference, Adaptive };
ModalScheme parseModalScheme(const std::string& name);  // std::invalid_argument if unknown
const std::vector<std::string>& modalSchemeNames();

struct ModalState {
  double t = 0.0;
  std::vector<double> q, v, a, f;  // f: generalized link force at (q, v)
};

class ModalIntegrator {
 public:
  ModalIntegrator(ModalScheme scheme, std::vector<double> omega2, std::vector<double> damping,
                  ModalForce& force, int refinement = 10);
  // Sets q, v at t, evaluates f and a.
  void initialize(ModalState& s, double t) const;
  // Advances by dt (in `substeps` equal sub-steps, times the adaptive refinement).
  // `onSubstep` (may be empty) is called after every sub-step but the step's last, with the
  // sub-step's end time (the state and the link forces are that sub-step's).
  void advance(ModalState& s, double dt, int substeps = 1,
               const std::function<void(double)>& onSubstep = {}) const;
  long long subStepsTaken() const { return subSteps_; }
  // Velocity at s.t: symplectic Euler's v is a half-step velocity (v(t - h/2)), so the
  // synchronized one is v + h/2 a; the central-difference v is already at s.t. Both add half
  // the last constraint impulse (the constraint force is not part of a). Energies use it,
  // which makes their error O(dt^2) for every scheme.
  std::vector<double> synchronizedVelocity(const ModalState& s) const;
  // Energy dissipated by modal damping since the start (trapezoidal in time).
  double modalDissipation() const { return dissipated_; }
  // The state s and what the integrator and the force carry ("modal/*"), and back.
  void archive(const ModalState& s, StateArchive& a) const;
  void restore(ModalState& s, const StateArchive& a) const;

 private:
  void euler(ModalState& s, double h) const;
  void central(ModalState& s, double h) const;
  double dampingPower(const ModalState& s) const;
  ModalScheme scheme_;
  std::vector<double> w2_, c_;
  ModalForce& force_;
  int refinement_;
  mutable long long subSteps_ = 0;
  mutable double lastStep_ = 0.0;
  mutable double dissipated_ = 0.0;
};


}  // namespace choc
