// The state of Coulomb friction inside the contact manager (ContactManager::Friction), shared
// by the implicit law (ContactFriction.cpp) and the explicit forward increments
// (ForwardIncrementFriction.cpp). Private to src/contact.
#pragma once
#include <vector>

#include "contact/ContactManager.hpp"
#include "contact/CoulombLaw.hpp"

namespace choc {

struct ContactManager::Friction {
  double kt = 0.0;
  struct Term {
    int k;          // index into contactDofs_
    int component;  // 0, 1, 2
    double coeff;   // 1 for the slave node, -w_i for a master node
    GO dof;
  };
  std::vector<std::vector<Term>> rel;  // per constraint: r = u_s - sum_i w_i u_i
  std::vector<Vec3> accepted, start;   // F at the last accepted step (in the plane), r(u_n)
  // Explicit central differences (forward increments, ForwardIncrementFriction.cpp): the
  // tangential forces are decided at each sub-step; accepted holds the last sub-step's forces,
  // start the relative positions they were decided at.
  bool increments = false;
  bool started = false;  // start holds the relative positions of a forward increment
  std::vector<char> acceptedStatus;
  double dissipated = 0.0;
  std::vector<double> pairWork;        // per pair: its part of dissipated
  double time = 0.0;                   // end of the current step
  // The last evaluation: the law's state per node (contact/CoulombLaw.hpp) and its normal force.
  mutable std::vector<CoulombPoint> point;
  mutable std::vector<double> normalForce;
  mutable long long evaluations = 0;
  // Within a step: each node's last slip direction and how often an iterate reversed it. An
  // iterate that slides against the node's last slip direction jumped over the stick band
  // 2 mu f_N / k_t (the slip tangent has no stiffness along the slip: Newton crosses the band
  // from side to side). Such an iterate is evaluated as sticking (the force F* and the stick
  // stiffness, a linear law): the next iterate lands where the stick force balances, inside
  // the band if the node sticks. Twice per node and step at most, so that Newton converges on
  // the Coulomb law itself.
  mutable std::vector<Vec3> lastDirection;
  mutable std::vector<int> reversals;
};

}  // namespace choc
