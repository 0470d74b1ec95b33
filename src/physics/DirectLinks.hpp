#pragma once
// Shock links of a direct transient: the modal transient's links (same input, same law,
// contact/ShockLaw) acting on the nodal unknowns. Each link is evaluated at its nodes'
// current positions X + u and velocities v, gathered on every rank (a few values per link),
// so every rank sees the same forces whatever the number of ranks. Its force enters the
// residual at the end of the step, like a contact force, with its tangent in the Newton
// matrix: d(force)/du + (dv/du) d(force)/dv, by central differences of the law (the same
// code for every shape, dashpot and friction).
// The tangential state (elastic spring, slip) advances only when a step is accepted.
// A dashpot makes the force jump where a link closes while approaching (F = Cn |delta'| at
// delta = 0-, 0 at 0+): a step can then have no solution, Newton alternating between open and
// pressing; after three switches in a step the link goes on without its dashpot for that step, a
// continuous law that has one (counted, and reported in the log).
// The rigid normal law is the modal transient's: here it is refused (use a contact pair with
// the Lagrange method for a rigid stop in a direct transient).
#include <array>
#include <vector>

#include "contact/MatrixEntry.hpp"
#include "core/TpetraTypes.hpp"
#include "physics/ShockLinks.hpp"

namespace choc {

class DirectLinks : public ShockLinkSet {
 public:
  // map: the DOF map. Throws InputError for a rigid law, naming the link.
  DirectLinks(std::vector<ShockLink> links, const Model& model, RCP<const Map> map);
  // The DOFs each link couples (its nodes' DX, DY, DZ unknowns), for the matrix graph.
  std::vector<std::vector<GO>> couplings() const;
  // Link i's DX, DY, DZ of node 1 then of node 2 (-1 where not an unknown).
  std::vector<GO> linkDofs(size_t i) const { return {dofs_[i].begin(), dofs_[i].end()}; }
  // The step about to be solved: its length (0 before the initial state) and a new tangent
  // for curved shapes in contact.
  void beginStep(double dt);
  // Evaluates every link at (u, v) from the state of the last accepted step (collective) and
  // adds the links' forces to the residual out (out -= force on the rows this rank owns).
  void addForces(const Vector& u, const Vector& v, Vector& out);
  // Key of the tangent: per link pressing (a normal force) and sliding at the last
  // evaluation, and the step for a curved shape in contact (its normal turns) or a sliding
  // link. The tangent is recomputed when it changes.
  std::vector<char> tangentKey() const;
  // d(residual)/du with dv/du = velocityFactor, on rows this rank owns: evaluated at the last
  // evaluation when the key or the factor changed, else the one evaluated then (so that a
  // restarted run factors the very matrix the uninterrupted run had).
  std::vector<MatrixEntry> tangent(double velocityFactor);
  // The step is accepted: the state at the last evaluation becomes the links' state
  // (restart/SteppedState.hpp); revert drops the last evaluation (the step was cut or failed).
  void commit();
  void revert() { pending_ = false; }
  void archive(StateArchive& a) const;
  // Steps in which a link went on without its dashpot (see addForces), over the run.
  long long dashpotDrops() const { return dashpotDrops_; }
  void restore(const StateArchive& a);

 private:
  Vec3 force(size_t i, const Vec3& d, const Vec3& w) const;  // on node 2, state not advanced
  ShockLawParameters lawOfStep(size_t i) const;  // the law, without the dashpot if dropped
  RCP<const Map> map_;
  std::vector<std::array<GO, 6>> dofs_;  // DX DY DZ of node 1, then of node 2 (-1: none)
  double length_ = 0.0;  // the mesh's extent: the scale of the difference steps
  double dt_ = 0.0;
  long long step_ = 0;
  bool pending_ = false;       // evaluated since the last commit
  std::vector<Vec3> d_, w_;    // relative position and velocity at the last evaluation
  std::vector<ShockResponse> trial_;
  // At the last accepted state: d, the dampers' force and the elastic law's tangential force.
  std::vector<Vec3> dPrev_, fdPrev_, ftPrev_;
  // Per link: d(force on node 2)/d(d) along u (row-major 3 x 3), and the key it was taken at.
  std::vector<std::array<double, 9>> jacobian_;
  std::vector<char> jacobianKey_;
  std::vector<int> switches_;     // per link: pressing <-> not pressing in this step's Newton
  std::vector<char> dashpotOff_;  // per link: the dashpot is dropped for this step
  long long dashpotDrops_ = 0;
};

}  // namespace choc
