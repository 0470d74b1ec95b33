#include "rigid/RotationStep.hpp"

#include <cmath>
#include <cstdio>

namespace choc {

namespace {

Vec3 scaled(const Vec3& a, double f) { return {a[0] * f, a[1] * f, a[2] * f}; }

Vec3 overInertia(const Vec3& J, const Vec3& p) { return {p[0] / J[0], p[1] / J[1], p[2] / J[2]}; }

// R turned about its own body axis k by the angle phi: R exp(phi e_k^).
void turnAboutBodyAxis(Matrix33& R, int k, double phi) {
  Vec3 axis{};
  axis[k] = phi;
  R = R * rotationFromVector(axis);
}

// The flow of pi_k^2 / (2 J_k) over h: the body turns about its axis k at Pi_k / J_k, which that
// turn leaves unchanged (Pi = R^T pi; pi itself is constant).
void flowAboutAxis(const Vec3& J, int k, double h, RotationState& s) {
  const Vec3 body = transpose(s.R) * s.momentum;
  turnAboutBodyAxis(s.R, k, h * body[k] / J[k]);
}

}  // namespace

Vec3 angularVelocity(const Vec3& J, const RotationState& s) {
  return s.R * overInertia(J, transpose(s.R) * s.momentum);
}

double rotationalEnergy(const Vec3& J, const RotationState& s) {
  return 0.5 * dot(s.momentum, angularVelocity(J, s));
}

RotationState stateFromAngularVelocity(const Vec3& J, const Matrix33& R, const Vec3& w) {
  const Vec3 wb = transpose(R) * w;
  RotationState s;
  s.R = R;
  s.momentum = R * Vec3{J[0] * wb[0], J[1] * wb[1], J[2] * wb[2]};
  return s;
}

// Strang's composition A1(h/2) A2(h/2) A3(h) A2(h/2) A1(h/2): symmetric, so second order; each
// factor exact, so pi is untouched and R stays a rotation (re-orthogonalised against the
// round-off of the products).
void rotateFreelyBySplitting(const Vec3& J, double h, RotationState& s) {
  flowAboutAxis(J, 0, 0.5 * h, s);
  flowAboutAxis(J, 1, 0.5 * h, s);
  flowAboutAxis(J, 2, h, s);
  flowAboutAxis(J, 1, 0.5 * h, s);
  flowAboutAxis(J, 0, 0.5 * h, s);
  s.R = reorthogonalized(s.R);
}

Vec3 midpointResidual(const Vec3& J, double h, const Vec3& bodyMomentum, const Vec3& nextBodyMomentum,
                      const Vec3& theta) {
  const Vec3 back = rotationFromVector(scaled(theta, -1.0)) * nextBodyMomentum;
  const Vec3 mid = overInertia(J, Vec3{bodyMomentum[0] + back[0], bodyMomentum[1] + back[1],
                                       bodyMomentum[2] + back[2]});
  return {theta[0] - 0.5 * h * mid[0], theta[1] - 0.5 * h * mid[1], theta[2] - 0.5 * h * mid[2]};
}

Matrix33 midpointTangent(const Vec3& J, double h, const Vec3& nextBodyMomentum, const Vec3& theta) {
  const Matrix33 D = derivativeOfRotatedBack(theta, nextBodyMomentum);
  Matrix33 T = unitMatrix33();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) T[3 * i + j] -= 0.5 * h * D[3 * i + j] / J[i];
  return T;
}

namespace {

// x = A^-1 b by Cramer's rule (a 3 x 3 system); false when A is singular to round-off.
bool solve3(const Matrix33& A, const Vec3& b, Vec3& x) {
  const Vec3 c0 = {A[0], A[3], A[6]}, c1 = {A[1], A[4], A[7]}, c2 = {A[2], A[5], A[8]};
  const double det = dot(c0, cross(c1, c2));
  const double scale = norm(c0) * norm(c1) * norm(c2);
  if (!(std::abs(det) > 1e-14 * scale)) return false;
  x = {dot(b, cross(c1, c2)) / det, dot(c0, cross(b, c2)) / det, dot(c0, cross(c1, b)) / det};
  return true;
}

}  // namespace

MidpointRotation rotateByMidpoint(const Vec3& J, double h, const Vec3& nextMomentum, RotationState& s,
                                  double tolerance, int maxIterations) {
  MidpointRotation out;
  const Matrix33 Rt = transpose(s.R);
  const Vec3 body = Rt * s.momentum, next = Rt * nextMomentum;
  Vec3 theta = scaled(overInertia(J, body), h);
  for (out.iterations = 0; out.iterations < maxIterations;) {
    const Vec3 g = midpointResidual(J, h, body, next, theta);
    Vec3 d{};
    if (!solve3(midpointTangent(J, h, next, theta), g, d)) {
      out.message = "the rotation's Newton tangent is singular (a step too long for the spin?)";
      return out;
    }
    theta = {theta[0] - d[0], theta[1] - d[1], theta[2] - d[2]};
    ++out.iterations;
    if (!std::isfinite(norm(theta))) break;
    if (norm(d) <= tolerance * norm(theta) || norm(d) <= 1e-300) {
      out.converged = true;
      break;
    }
  }
  if (!out.converged) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "the rotation's Newton did not converge in %d iterations (|theta| = %.3e)",
                  out.iterations, norm(theta));
    out.message = buf;
    return out;
  }
  out.theta = theta;
  s.R = reorthogonalized(s.R * rotationFromVector(theta));
  s.momentum = nextMomentum;
  return out;
}

}  // namespace choc
