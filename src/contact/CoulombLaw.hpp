// The Coulomb friction law of one contact node: the friction layer of contact, apart from the
// pairing, the gaps and the active set (ContactManager keeps, per node, the accepted force, the
// start of the step's relative motion and the iteration control).
//
// Elastic-plastic on the step's relative tangential motion delta = P (r - r_n), P = I - n n^T:
// the trial force F* = P F_n - k_t delta; stick while |F*| <= mu f_N (F = F*), slip otherwise,
// returned onto the cone (F = mu f_N F* / |F*|). The consistent tangent -dF/d(delta) is
//   stick:  k_t P
//   slip:   (mu f_N k_t / |F*|) (P - t t^T),  t = F* / |F*|,
// plus, while slipping, the normal force's variation along t (dF/d f_N = mu t), which the
// manager adds through its constraint rows.
#pragma once
#include "core/Vec3.hpp"

namespace choc {

// The in-plane part of v: P v.
Vec3 inPlane(const Vec3& v, const Vec3& n);

struct CoulombPoint {
  int status = 0;        // 1 stick, 2 slip
  Vec3 trial{0, 0, 0};   // F*
  double trialNorm = 0;  // |F*|
  Vec3 direction{0, 0, 0};  // t (slip)
  Vec3 force{0, 0, 0};   // F
};

// The trial state at the accepted force `accepted`, the relative motion `delta` since the
// step's start (its normal part is dropped), the normal n (unit) and the stick stiffness kt.
CoulombPoint coulombTrial(const Vec3& accepted, const Vec3& delta, const Vec3& n, double kt);
// The return onto the cone of the coefficient mu at the normal force fn > 0: sets the status,
// the force and, slipping, the direction. `forceStick`: evaluate as sticking even beyond the
// cone (the manager's control of iterates that jump the stick band).
void coulombReturn(CoulombPoint& p, double mu, double fn, bool forceStick = false);

// The scale of the tangent -dF/d(delta): k_t (stick), mu f_N k_t / |F*| (slip); and its
// projector's entry (a, b): P_ab (stick), (P - t t^T)_ab (slip).
double coulombTangentScale(const CoulombPoint& p, double kt, double mu, double fn);
double coulombProjector(const CoulombPoint& p, const Vec3& n, int a, int b);

}  // namespace choc
