// The contact geometry: the node-to-face pairs of every contact pair (followed surfaces,
// rigid obstacles), the linearised gaps g_s(u) = g0_s + B_s u, the enforcement method, and the
// active set the contact strategy decides (contact/ContactStrategy.hpp: each slave node's status
// and pressure lambda_s [N, compression positive], kept here because following a surface opens
// a constraint and the reports read them). It applies the contact forces of the current statuses.
// Every rank holds all the constraints (a few per contact face): values at the contact DOFs are
// summed across ranks, so every rank sees the same gaps, statuses and pressures whatever the
// number of ranks.
#pragma once
#include <array>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "contact/ContactActiveSet.hpp"
#include "contact/ContactMethod.hpp"
#include "contact/ContactPairing.hpp"
#include "contact/CoulombFriction.hpp"
#include "contact/MatrixEntry.hpp"
#include "contact/FollowedSurfaces.hpp"
#include "fem/DofMap.hpp"
#include "core/TpetraTypes.hpp"
#include "fem/ElementValidity.hpp"
#include "mesh/Mesh.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

struct ContactConstraint {
  SlaveProjection geometry;
  std::vector<std::pair<GO, double>> terms;  // B_s: (global DOF, coefficient)
  int owner = 0;                             // rank owning the slave node (multiplier row)
  // Against a rigid obstacle: the slave node's reference position and, per component, the
  // index of its term (-1 when the component is not an unknown).
  Point3 reference{};
  std::array<int, 3> componentTerm{-1, -1, -1};
};

// The constraint of one slave node: B_s u = n . (u_s - sum_i w_i u_i) over the slave node and
// its master face's nodes (merged DOFs, sorted). allComponents keeps every component of the
// slave and master nodes even where n is zero (normals that turn: the matrix graph must hold
// every coupling).
ContactConstraint makeContactConstraint(const Point3& reference, const DofMap& dofs,
                                        const SlaveProjection& sp, bool allComponents);

// A pair that cannot be set up (no slave node within the search distance, a slave node where
// an obstacle's normal is undefined...): which pair, and why.
struct PairingError : std::invalid_argument {
  PairingError(int p, const std::string& what) : std::invalid_argument(what), pair(p) {}
  int pair;
};

struct StatusUpdate {
  bool changed = false;
  int active = 0, entered = 0, left = 0;
  std::string where;  // the pairs whose nodes switched, e.g. "pair 'wall' (node 12, ...)"
};

// Per constraint and component d the terms of u_s,d - sum_i w_i u_i,d over every component (not
// only the normal's), indexing dofs (every component of the slave and master nodes, sorted).
struct SlipTerms {
  std::vector<GO> dofs;
  std::vector<std::array<std::vector<std::pair<int, double>>, 3>> terms;
};

// u at the given DOFs, summed across ranks (the same array on every rank). Collective.
std::vector<double> gatherReplicated(const Map& map, const std::vector<GO>& dofs, const Vector& u);

class ContactManager {
 public:
  // Throws PairingError naming the pair and side set.
  ContactManager(const Mesh& mesh, const DofMap& dofs, RCP<const Map> map,
                 const std::vector<PairDefinition>& pairs, std::unique_ptr<ContactMethod> method);
  ~ContactManager();

  const ContactMethod& method() const { return *method_; }
  int numConstraints() const { return static_cast<int>(constraints_.size()); }
  const std::vector<ContactConstraint>& constraints() const { return constraints_; }
  int numPairs() const { return static_cast<int>(pairs_.size()); }
  const PairDefinition& pair(int p) const { return pairs_[p]; }
  int unpairedNodes() const { return unpaired_; }

  // Tangential slip of each slave node at u and time t [m]: the length of the tangential part
  // of its displacement relative to its master point (or to the moving obstacle) since t = 0;
  // on a followed surface, the path length of its slip while in contact (commitMotion).
  // Collective; the same array on every rank.
  std::vector<double> slips(const Vector& u, double t) const;
  // Gaps at u (the same array on every rank).
  std::vector<double> gaps(const Vector& u) const;
  // d(gap)/dt at velocity v (B_s v, less the obstacle's velocity along its normal). Collective.
  std::vector<double> gapRates(const Vector& v) const;
  // Normal force of each node at u with the current statuses and pressures.
  std::vector<double> forces(const Vector& u) const;
  // out -= f_s B_s^T on the rows this rank owns, and friction's forces (a trial of its law);
  // returns the norm of the constraint equations' residual (multiplier rows, force units; 0 for
  // penalty).
  double addForces(const Vector& u, Vector& out);
  // u at the contact DOFs (every constraint's terms, sorted; replicated), and the gaps of such values.
  std::vector<double> contactValues(const Vector& u) const;
  std::vector<double> gapsAt(const std::vector<double>& x) const;
  const std::vector<GO>& contactDofs() const { return contactDofs_; }
  // Per constraint: its terms as (index into the contact DOFs, coefficient).
  const std::vector<std::vector<std::pair<int, double>>>& localTerms() const { return localTerms_; }

  // Before each step (and the initial state): the constraints against rigid obstacles are
  // re-linearised at u (the last accepted state) with the obstacles placed at time t:
  // gap(u') = d(x + u) + n . (u' - u), n the obstacle's normal at x + u. Collective. Throws
  // NumericalError when a node reaches a point where the normal is undefined.
  // Pairs with 'Search' = current are paired again first, on the configuration at u: each
  // slave node with the closest point of its master surface (SurfaceSearch), the constraint
  // re-linearised there, gap(u') = g(u) + n . ((u'_s - u_s) - sum_i w_i (u'_i - u_i)); a node
  // whose search finds no face within the search distance has no constraint (inactive) until
  // one does. Coefficients that move by less than 1e-6 are kept (no refactorisation).
  // dt: the step's length (0 before the initial state), for the friction's start of step.
  void beginStep(const Vector& u, double t, double dt = 0.0);
  // Bumped whenever a constraint's coefficients B_s change (curved obstacles, followed surfaces).
  int geometryVersion() const { return geometryVersion_; }
  // Bumped whenever a constraint couples other DOFs (a slave node of a followed surface moved
  // to another master face): the effective matrix needs a new graph.
  int topologyVersion() const { return topologyVersion_; }
  // An accepted step ending at u: each active node of a followed surface adds to its slip the
  // tangential motion relative to its master point since beginStep. Collective.
  void commitMotion(const Vector& u);
  long long searchProjections() const { return followed_ ? followed_->projections() : 0; }
  // Slave nodes through a rigid obstacle by more than a fraction of their faces' size (the
  // shortest edge of the slave faces around the node): past kPenetrationWarning a warning, past
  // kPenetrationLimit a failure (ElementValidity's lines; contact/ObstaclePenetration.cpp).
  // Collective; the same on every rank.
  static constexpr double kPenetrationWarning = 0.1, kPenetrationLimit = 0.5;
  void checkPenetration(const Vector& u, ElementValidity& v) const;

  // Coulomb friction (pairs with 'Friction Coefficient' mu > 0): a layer of its own
  // (CoulombFriction.hpp) over this manager's constraints; null without friction.
  bool hasFriction() const { return friction_ != nullptr; }
  const CoulombFriction* friction() const { return friction_.get(); }
  CoulombFriction* friction() { return friction_.get(); }

  // Statuses, pressures and the multiplier scale in a checkpoint ("contact/*"), and back.
  void archive(StateArchive& a) const;
  void restore(const StateArchive& a);

  // The active set (the strategy's decisions: statuses, pressures, their accepted copies, scale).
  ContactActiveSet& activeSet() { return set_; }
  const ContactActiveSet& activeSet() const { return set_; }
  const std::vector<char>& status() const { return set_.status; }
  int activeCount() const { return set_.activeCount(); }
  // Per pair, its slave nodes in contact: "pair 'slide': 28 of 28 nodes in contact, ...".
  std::string activeSummary() const;
  double energy(const Vector& u) const;
  RCP<const Comm> comm() const { return map_->getComm(); }

 private:
  void indexTerms();
  void followSurfaces(const Vector& u);
  void placeObstacles(const Vector& u, double t);
  std::unique_ptr<CoulombFriction> friction_;  // null without friction
  void archivePairing(StateArchive& a) const;
  void restorePairing(const StateArchive& a);
  SlipTerms slipTerms_;  // the relative motion of every constraint, for the slips
  std::vector<PairDefinition> pairs_;
  std::unique_ptr<ContactMethod> method_;
  RCP<const Map> map_;
  std::vector<ContactConstraint> constraints_;
  std::vector<GO> contactDofs_;                // sorted distinct DOFs of all B_s
  std::vector<std::vector<std::pair<int, double>>> localTerms_;  // index into contactDofs_
  ContactActiveSet set_;  // statuses, pressures, their accepted copies, scale, version
  int unpaired_ = 0;
  int geometryVersion_ = 0, topologyVersion_ = 0;
  std::unique_ptr<FollowedSurfaces> followed_;  // null without 'Search' = current pairs
  const DofMap* dofs_ = nullptr;
  std::vector<double> slip_;     // followed surfaces: accumulated slip [m]
  std::vector<Vec3> slipStart_;  // tangential offset at the last beginStep
  bool paired_ = false;          // slipStart_ holds the offsets of the current pairing
  bool hasObstacles_ = false, hasCurvedObstacles_ = false;
  std::vector<double> slaveSize_;  // per constraint against an obstacle: its slave faces' shortest edge
};

// Per constraint against an obstacle: the shortest edge of its slave node's faces (0 elsewhere).
std::vector<double> slaveFaceSizes(const Mesh& mesh, const std::vector<PairDefinition>& pairs,
                                   const std::vector<ContactConstraint>& constraints);

// Power [W] the moving rigid obstacles give the body at u: the sum over their slave nodes of the
// normal force times the obstacle's velocity along the normal (0 without obstacles). Collective.
double obstaclePowerAt(const ContactManager& contact, const Vector& u);

// Per mesh node: 1 for the nodes of every pair's master and slave side sets.
std::vector<char> contactSurfaceNodes(const ContactManager& contact, const Mesh& mesh);

}  // namespace choc
