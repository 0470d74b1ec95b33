#include "contact/CoulombLaw.hpp"

namespace choc {

Vec3 inPlane(const Vec3& v, const Vec3& n) {
  const double vn = dot(v, n);
  return Vec3{v[0] - vn * n[0], v[1] - vn * n[1], v[2] - vn * n[2]};
}

CoulombPoint coulombTrial(const Vec3& accepted, const Vec3& delta, const Vec3& n, double kt) {
  CoulombPoint p;
  const Vec3 d = inPlane(delta, n);
  const Vec3 old = inPlane(accepted, n);
  p.trial = Vec3{old[0] - kt * d[0], old[1] - kt * d[1], old[2] - kt * d[2]};
  p.trialNorm = norm(p.trial);
  return p;
}

void coulombReturn(CoulombPoint& p, double mu, double fn, bool forceStick) {
  if (p.trialNorm <= mu * fn || forceStick) {
    p.status = 1;
    p.force = p.trial;
    return;
  }
  p.status = 2;
  for (int k = 0; k < 3; ++k) {
    p.direction[k] = p.trial[k] / p.trialNorm;
    p.force[k] = mu * fn * p.direction[k];
  }
}

double coulombTangentScale(const CoulombPoint& p, double kt, double mu, double fn) {
  return p.status == 2 ? mu * fn * kt / p.trialNorm : kt;
}

double coulombProjector(const CoulombPoint& p, const Vec3& n, int a, int b) {
  double q = (a == b ? 1.0 : 0.0) - n[a] * n[b];
  if (p.status == 2) q -= p.direction[a] * p.direction[b];
  return q;
}

}  // namespace choc
