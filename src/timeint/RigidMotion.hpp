// The rigid bodies of an explicit run as central differences see them (physics/RigidBodies.hpp):
// the rows of their nodes are not advanced by M^-1 r (their inverse mass is 0) but placed by the
// bodies, which the forces on those rows move (docs/theory/rigid-bodies.md, section 4).
#pragma once
#include "core/TpetraTypes.hpp"

namespace choc {

class RigidMotion {
 public:
  virtual ~RigidMotion() = default;
  // At the start, u and v the initial fields: the bodies take the motion the nodes' initial
  // velocities give them, and their rows of v are set to it.
  virtual void start(const Vector& u, Vector& v) = 0;
  // Then, r the forces' residual of the initial state (a = -M^-1 r): their rows of a.
  virtual void accelerate(const Vector& r, Vector& a) = 0;
  // For exactly enforced contact: the bodies' rows of uStar where the forces -r would put them
  // at the end of the next sub-step h, factor h^2 the displacement an acceleration gives there
  // (1/2 from the initial state, 1 between sub-steps).
  virtual void predict(double h, double factor, const Vector& r, Vector& uStar) = 0;
  // The first half of a step: a kick by the last forces over h/2, the drift over h; u and vHalf
  // set on the bodies' rows.
  virtual void drift(double h, Vector& u, Vector& vHalf) = 0;
  // The second half: the forces -r at the drifted positions kick over h/2; v and a set on the
  // bodies' rows.
  virtual void kick(double h, const Vector& r, Vector& v, Vector& a) = 0;
};

}  // namespace choc
