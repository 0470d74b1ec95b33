// The rigid bodies that move some contact DOFs (rigid blocks: physics/RigidBodies.hpp), as
// exactly enforced contact sees them: a force on such a DOF moves its whole body, so the
// forward increments (contact/ForwardIncrementSolver.hpp) need, per contact DOF, its body,
// component and lever arm, and each body's inverse mass and inertia, in the current
// configuration.
#pragma once
#include <vector>

#include "contact/ForwardIncrementSolver.hpp"
#include "core/TpetraTypes.hpp"

namespace choc {

class ContactBodies {
 public:
  virtual ~ContactBodies() = default;
  // dofs: global DOF ids (every rank the same list); the same answer on every rank.
  virtual RigidContactBodies describe(const std::vector<GO>& dofs) const = 0;
};

}  // namespace choc
