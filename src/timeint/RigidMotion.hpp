// The rigid bodies of an explicit run as central differences see them (physics/RigidBodies.hpp):
// the rows of their nodes are not advanced by M^-1 r (their inverse mass is 0) but placed by the
// bodies, which the forces on those rows move (docs/theory/rigid-bodies.md, section 4).
#pragma once
#include "core/TpetraTypes.hpp"

namespace choc {

class RigidMotion {
 public:
  virtual ~RigidMotion() = default;
  // At the start, u and v the initial fields and r the forces' residual there (a = -M^-1 r): the
  // bodies take the motion the nodes' initial velocities give them, and their rows of v and a
  // are set to it.
  virtual void start(const Vector& u, const Vector& r, Vector& v, Vector& a) = 0;
  // The first half of a step: a kick by the last forces over h/2, the drift over h; u and vHalf
  // set on the bodies' rows.
  virtual void drift(double h, Vector& u, Vector& vHalf) = 0;
  // The second half: the forces -r at the drifted positions kick over h/2; v and a set on the
  // bodies' rows.
  virtual void kick(double h, const Vector& r, Vector& v, Vector& a) = 0;
};

}  // namespace choc
