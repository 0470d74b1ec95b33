// J2 plasticity's return maps and consistent tangents (formulas in the header).
#include "materials/J2Plasticity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "materials/NearScalarLog.hpp"
#include "materials/SymmetricEigen.hpp"

namespace choc {

namespace {

const double kSqrt23 = std::sqrt(2.0 / 3.0);
constexpr int kPairs[6][2] = {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}};

Mat3 symmetricFromState(const double* s) {
  Mat3 m{};
  for (int k = 0; k < 6; ++k) m[kPairs[k][0]][kPairs[k][1]] = m[kPairs[k][1]][kPairs[k][0]] = s[k];
  return m;
}

void stateFromSymmetric(const Mat3& m, double* s) {
  for (int k = 0; k < 6; ++k) s[k] = 0.5 * (m[kPairs[k][0]][kPairs[k][1]] + m[kPairs[k][1]][kPairs[k][0]]);
}

// (eps_A - eps_B) / (x_A - x_B) with eps = ln(x) / 2, continuous where x_B -> x_A (1 / 2 x_A).
double logSlope(double xA, double xB) {
  const double t = (xB - xA) / xA;
  if (std::abs(t) < 1e-4) return (1 - t / 2 + t * t / 3) / (2 * xA);
  return std::log1p(t) / (2 * t * xA);
}

// The increment's dissipated work (header) from the last accepted W, P, F in `old`, and the new
// W, P, F into the state.
void recordIncrement(const Mat3& F, const double* old, J2Response& out) {
  double work = -(out.energy - old[kJ2Energy]);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const int k = 3 * i + j;
      work += 0.5 * (old[kJ2Stress + k] + out.P[i][j]) * (F[i][j] - old[kJ2Deformation + k]);
      out.state[size_t(kJ2Stress + k)] = out.P[i][j];
      out.state[size_t(kJ2Deformation + k)] = F[i][j];
    }
  out.state[kJ2Energy] = out.energy;
  out.plasticWork = work;
}

// D_ikmq = sum_AB dtdx_AB v_iA v_kA v_mB v_qB + sum_(A != B) c_AB / 2 (v_iA v_mA v_qB v_kB +
// v_iA v_qA v_mB v_kB), summed as sum_A Nd_A,ik Q_A,mq (Nd_A = v_A (x) v_A, Q_A = sum_B dtdx_AB
// Nd_B) plus, for A != B, M_ik (c_AB / 2) (M_mq + M_qm) with M = v_A (x) v_B: the dyads formed
// once, a sixth of the four-index sum's products.
void principalAxesTangent(const Mat3& v, const double (*dtdx)[3], const double (*c)[3], double (*D)[3][3][3]) {
  double Nd[3][3][3], Q[3][3][3];
  for (int A = 0; A < 3; ++A)
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k) Nd[A][i][k] = v[i][A] * v[k][A];
  for (int A = 0; A < 3; ++A)
    for (int m = 0; m < 3; ++m)
      for (int q = 0; q < 3; ++q)
        Q[A][m][q] = dtdx[A][0] * Nd[0][m][q] + dtdx[A][1] * Nd[1][m][q] + dtdx[A][2] * Nd[2][m][q];
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int m = 0; m < 3; ++m)
        for (int q = 0; q < 3; ++q)
          D[i][k][m][q] = Nd[0][i][k] * Q[0][m][q] + Nd[1][i][k] * Q[1][m][q] + Nd[2][i][k] * Q[2][m][q];
  for (int A = 0; A < 3; ++A)
    for (int B = 0; B < 3; ++B) {
      if (A == B || c[A][B] == 0.0) continue;
      double M[3][3], S[3][3];
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k) M[i][k] = v[i][A] * v[k][B];
      for (int m = 0; m < 3; ++m)
        for (int q = 0; q < 3; ++q) S[m][q] = 0.5 * c[A][B] * (M[m][q] + M[q][m]);
      for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
          for (int m = 0; m < 3; ++m)
            for (int q = 0; q < 3; ++q) D[i][k][m][q] += M[i][k] * S[m][q];
    }
}

Mat3 scaled(Mat3 a, double s) {
  for (auto& row : a)
    for (double& v : row) v *= s;
  return a;
}

}  // namespace

namespace {

// The flow-stress law the parameters give (J2Parameters), validated.
FlowStress flowOf(const J2Parameters& p) {
  std::ostringstream msg;
  if (!(p.youngsModulus > 0) || !(p.poissonsRatio > -1.0 && p.poissonsRatio < 0.5))
    msg << "needs Young's modulus > 0 and Poisson's ratio in (-1, 0.5), got E = " << p.youngsModulus
        << ", nu = " << p.poissonsRatio;
  else if (p.johnsonCook)
    return FlowStress::johnsonCook(p.jc);
  else if (!p.curve.strain.empty())
    return FlowStress::curve(p.curve);
  else if (!(p.yieldStress > 0))
    msg << "needs a yield stress > 0, got " << p.yieldStress << " Pa";
  else if (!(p.hardening >= 0) || !std::isfinite(p.hardening))
    msg << "needs a hardening modulus >= 0, got " << p.hardening << " Pa";
  if (!msg.str().empty()) throw std::invalid_argument("J2 plasticity material: " + msg.str());
  return FlowStress::linear(p.yieldStress, p.hardening);
}

}  // namespace

J2Plasticity::J2Plasticity(const J2Parameters& p, bool finiteStrain)
    : p_(p), flow_(flowOf(p)), damage_(p.damage, p.jc), finite_(finiteStrain) {
  if (p.damage.enabled && !p.johnsonCook)
    throw std::invalid_argument("J2 plasticity material: Johnson-Cook damage needs the Johnson-Cook model");
  mu_ = p.youngsModulus / (2 * (1 + p.poissonsRatio));
  kappa_ = p.youngsModulus / (3 * (1 - 2 * p.poissonsRatio));
  hk_ = p.kinematicHardening;
  std::ostringstream msg;
  if (!(hk_ >= 0) || !std::isfinite(hk_))
    msg << "needs a kinematic hardening modulus >= 0, got " << hk_ << " Pa";
  else if (hk_ > 0 && finite_)
    msg << "kinematic hardening is small-strain only (a kinematic hardening modulus of " << hk_
        << " Pa on a finite-strain block)";
  if (!msg.str().empty()) throw std::invalid_argument("J2 plasticity material: " + msg.str());
}

J2Plasticity::Return J2Plasticity::radialReturn(double normE, const double* old, double dt) const {
  Return r;
  const double alpha = old[kJ2Alpha], T = old[kJ2Temperature];
  FlowStress::Value at = flow_.at(alpha, 0.0, dt, T);
  const double trial = 2 * mu_ * normE, f0 = trial - kSqrt23 * at.stress;
  r.flowStress = at.stress;
  if (!(f0 > 0)) return r;
  r.yielded = true;
  if (flow_.isLinear()) {
    r.dgamma = f0 / (2 * mu_ + 2.0 / 3.0 * hk_ + 2.0 / 3.0 * flow_.linearHardening());
    at = flow_.at(alpha, kSqrt23 * r.dgamma, dt, T);
  } else {
    r.dgamma = solveReturn(trial, f0, old, dt, at);
  }
  r.flowStress = at.stress;
  r.theta = 1 - r.dgamma / normE;
  r.thetabar = 1 / (1 + (at.slope + hk_) / (3 * mu_)) - (1 - r.theta);
  return r;
}

// g(x) = trial - (2 mu + 2/3 H_k) x - sqrt(2/3) sigma_y(alpha + sqrt(2/3) x) decreases from g(0) = f0 > 0
// to g(f0 / 2 mu) <= 0: Newton from the upper end (g is convex for the concave laws, so the
// iterates then rise to the root), a bisection whenever a step leaves the bracket.
double J2Plasticity::solveReturn(double trial, double f0, const double* old, double dt,
                                 FlowStress::Value& at) const {
  const double alpha = old[kJ2Alpha], T = old[kJ2Temperature];
  double lo = 0.0, hi = f0 / (2 * mu_), x = hi;
  for (int it = 0; it < 200; ++it) {
    at = flow_.at(alpha, kSqrt23 * x, dt, T);
    const double g = trial - (2 * mu_ + 2.0 / 3.0 * hk_) * x - kSqrt23 * at.stress;
    if (std::abs(g) <= 1e-13 * trial || hi - lo <= 1e-15 * hi) return x;
    (g > 0 ? lo : hi) = x;
    const double step = x + g / (2 * mu_ + 2.0 / 3.0 * hk_ + 2.0 / 3.0 * at.slope);
    x = step > lo && step < hi ? step : 0.5 * (lo + hi);
  }
  std::ostringstream msg;
  msg << "the return map of the " << flow_.describe() << " did not converge in 200 iterations (trial stress "
      << trial << " Pa, equivalent plastic strain " << alpha << ", increment " << dt << " s): "
      << (flow_.hasTemperature() ? "its rate term 1 + C ln(rate / rate_0) and hardening B alpha^n drive it: check "
                                   "'Johnson-Cook C', 'Reference Strain Rate', 'Johnson-Cook B' and 'Johnson-Cook n'"
                                 : "check the flow stress's parameters");
  throw std::domain_error(msg.str());
}

std::array<double, kJ2StateSize> J2Plasticity::initialState() const {
  std::array<double, kJ2StateSize> s{};
  if (finite_) s[0] = s[1] = s[2] = 1.0;  // C_p^-1 = I
  s[kJ2Temperature] = flow_.initialTemperature();
  s[kJ2Deformation] = s[kJ2Deformation + 4] = s[kJ2Deformation + 8] = 1.0;  // F = I
  return s;
}

void J2Plasticity::respond(const Mat3& F, const double* old, bool withTangent, J2Response& out,
                          bool elasticTangent, double dt) const {
  if (finite_)
    respondFinite(F, old, withTangent, elasticTangent, dt, out);
  else
    respondSmall(F, old, withTangent, elasticTangent, dt, out);
  accumulateDamage(old, dt, out);
}

void J2Plasticity::accumulateDamage(const double* old, double dt, J2Response& out) const {
  out.state[kJ2Damage] = old[kJ2Damage];
  const double dalpha = out.state[kJ2Alpha] - old[kJ2Alpha];
  if (!damage_.enabled() || !(dalpha > 0)) return;
  const double equivalent = vonMises(out.cauchy);  // the flow stress: > 0 at a yielding point
  const double triaxiality = equivalent > 0 ? trace(out.cauchy) / (3 * equivalent) : 0.0;
  const double failure = damage_.failureStrain(triaxiality, dalpha, dt, old[kJ2Temperature]);
  out.state[kJ2Damage] += dalpha / std::max(failure, std::numeric_limits<double>::min());
}

// What both kinematics end a point with: alpha, the stored energy K/2 (tr eps)^2 + mu ||theta e||^2
// (dev eps_e = theta e), the increment's work and the temperature (that work's heat).
void J2Plasticity::finishPoint(const Mat3& F, const double* old, const Return& r, double tr, double normE,
                               J2Response& out, const double* storedEnergy) const {
  const double dalpha = kSqrt23 * r.dgamma;
  out.state[kJ2Alpha] = old[kJ2Alpha] + dalpha;
  out.yielded = r.yielded;
  out.energy = storedEnergy ? *storedEnergy : 0.5 * kappa_ * tr * tr + mu_ * r.theta * r.theta * normE * normE;
  recordIncrement(F, old, out);
  // The heat: chi sigma_y d alpha / (rho c), sigma_y the increment's flow stress (Kirchhoff's in
  // finite strain, per reference volume): never negative, nothing where the point does not yield.
  out.state[kJ2Temperature] = old[kJ2Temperature] + flow_.heatPerWork() * r.flowStress * dalpha;
}

void J2Plasticity::respondSmall(const Mat3& F, const double* old, bool withTangent, bool elastic, double dt,
                               J2Response& out) const {
  const Mat3 epsP = symmetricFromState(old);
  const Mat3 beta = symmetricFromState(old + kJ2BackStress);  // zero without kinematic hardening
  Mat3 e{};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) e[i][j] = 0.5 * (F[i][j] + F[j][i]) - (i == j ? 1.0 : 0.0) - epsP[i][j];
  const double tr = trace(e);
  for (int i = 0; i < 3; ++i) e[i][i] -= tr / 3;
  for (int i = 0; i < 3; ++i)  // the relative stress over 2 mu: dev eps_e - beta / 2 mu
    for (int j = 0; j < 3; ++j) e[i][j] -= beta[i][j] / (2 * mu_);
  const double normE = std::sqrt(contract(e, e));
  const Return r = radialReturn(normE, old, dt);
  const Mat3 n = r.yielded ? scaled(e, 1 / normE) : Mat3{};
  for (int i = 0; i < 3; ++i)  // dev sigma = beta + 2 mu theta (relative strain)
    for (int j = 0; j < 3; ++j)
      out.P[i][j] = 2 * mu_ * r.theta * e[i][j] + beta[i][j] + (i == j ? kappa_ * tr : 0.0);
  out.cauchy = out.P;
  Mat3 epsPNew = epsP, betaNew = beta;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      epsPNew[i][j] += r.dgamma * n[i][j];
      betaNew[i][j] += 2.0 / 3.0 * hk_ * r.dgamma * n[i][j];
    }
  stateFromSymmetric(epsPNew, out.state.data());
  stateFromSymmetric(betaNew, out.state.data() + kJ2BackStress);
  if (hk_ > 0) {  // K/2 (tr eps)^2 + ||dev sigma||^2 / 4 mu + 3/4 ||beta||^2 / H_k
    Mat3 s = out.P;
    for (int i = 0; i < 3; ++i) s[i][i] -= kappa_ * tr;
    const double stored = 0.5 * kappa_ * tr * tr + contract(s, s) / (4 * mu_) + 0.75 * contract(betaNew, betaNew) / hk_;
    finishPoint(F, old, r, tr, normE, out, &stored);
  } else {
    finishPoint(F, old, r, tr, normE, out);
  }
  if (!withTangent) return;
  const double theta = elastic ? 1.0 : r.theta, thetabar = elastic ? 0.0 : r.thetabar;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      for (int k = 0; k < 3; ++k)
        for (int l = 0; l < 3; ++l) {
          const double dd = (i == j) * (k == l);
          const double sym = 0.5 * ((i == k) * (j == l) + (i == l) * (j == k));
          out.A[3 * i + j][3 * k + l] =
              kappa_ * dd + 2 * mu_ * theta * (sym - dd / 3) - 2 * mu_ * thetabar * n[i][j] * n[k][l];
        }
}

void J2Plasticity::respondFinite(const Mat3& F, const double* old, bool withTangent, bool elastic, double dt,
                                J2Response& out) const {
  const double J = determinant(F);
  if (!(J > 0)) {
    std::ostringstream msg;
    msg << "J2 plasticity material: det F = " << J << " <= 0 (an inverted or collapsed point)";
    throw std::domain_error(msg.str());
  }
  const Mat3 Fi = inverse(F, J);
  const Mat3 FG = multiply(F, symmetricFromState(old));
  Mat3 be = multiply(FG, transpose(F));
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) be[i][j] = be[j][i] = 0.5 * (be[i][j] + be[j][i]);
  if (!withTangent && respondFiniteBySeries(F, Fi, J, be, old, dt, out)) return;
  const SymmetricEigen eig = symmetricEigen(be);
  double x[3], eps[3], e[3], n[3] = {0, 0, 0};
  for (int A = 0; A < 3; ++A) {
    x[A] = eig.values[A];
    if (!(x[A] > 0)) throw std::domain_error("J2 plasticity material: the elastic stretch is not positive");
    eps[A] = 0.5 * std::log(x[A]);
  }
  const double tr = eps[0] + eps[1] + eps[2];
  for (int A = 0; A < 3; ++A) e[A] = eps[A] - tr / 3;
  const double normE = std::sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
  const Return r = radialReturn(normE, old, dt);
  if (r.yielded)
    for (int A = 0; A < 3; ++A) n[A] = e[A] / normE;
  const Mat3& v = eig.vectors;
  Mat3 tauM{};
  for (int A = 0; A < 3; ++A) {
    const double tau = kappa_ * tr + 2 * mu_ * r.theta * e[A];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) tauM[i][j] += tau * v[i][A] * v[j][A];
  }
  Mat3 beNew{};
  if (r.yielded)  // b_e = exp(2 (eps - dgamma n)) on the trial's axes
    for (int A = 0; A < 3; ++A) {
      const double xe = std::exp(2 * (eps[A] - r.dgamma * n[A]));
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) beNew[i][j] += xe * v[i][A] * v[j][A];
    }
  finishFinitePoint(F, Fi, J, tauM, r.yielded ? &beNew : nullptr, old, r, tr, normE, out);
  if (!withTangent) return;
  const double theta = elastic ? 1.0 : r.theta, thetabar = elastic ? 0.0 : r.thetabar;
  finiteTangent(eig, x, n, theta, thetabar, FG, Fi, out);
}

// The same update with eps = log(b_e) / 2 as a matrix: its trace ln(det b_e) / 2, its deviator
// e = log(bbar) / 2; tau = kappa tr I + 2 mu theta e (the principal-axis sum above, summed), and
// at a yielding point b_e = exp(2 (eps - dgamma e / ||e||)) = exp(2 tr / 3) exp(2 (1 - dgamma /
// ||e||) e), all of them coaxial.
bool J2Plasticity::respondFiniteBySeries(const Mat3& F, const Mat3& Fi, double J, const Mat3& be, const double* old,
                                         double dt, J2Response& out) const {
  Mat3 logBar;
  double lnDet = 0.0;
  if (!logNearScalar(be, logBar, lnDet)) return false;
  const double tr = 0.5 * lnDet;
  const Mat3 e = scaled(logBar, 0.5);  // logBar is a deviator
  const double normE = std::sqrt(contract(e, e));
  const Return r = radialReturn(normE, old, dt);
  Mat3 tauM;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) tauM[i][j] = 2 * mu_ * r.theta * e[i][j] + (i == j ? kappa_ * tr : 0.0);
  Mat3 beNew{};
  if (r.yielded) beNew = scaled(expSmall(scaled(e, 2 * (1 - r.dgamma / normE))), std::exp(2 * tr / 3));
  finishFinitePoint(F, Fi, J, tauM, r.yielded ? &beNew : nullptr, old, r, tr, normE, out);
  return true;
}

// Both finite-strain updates' end: P = tau F^-T, sigma = tau / J, C_p^-1 = F^-1 b_e F^-T at a
// yielding point (beNew), else unchanged (F^-1 b_e^trial F^-T = G exactly; without the
// round-off), then the point's scalars.
void J2Plasticity::finishFinitePoint(const Mat3& F, const Mat3& Fi, double J, const Mat3& tau, const Mat3* beNew,
                                     const double* old, const Return& r, double tr, double normE,
                                     J2Response& out) const {
  out.P = multiply(tau, transpose(Fi));
  out.cauchy = scaled(tau, 1 / J);
  if (beNew)
    stateFromSymmetric(multiply(multiply(Fi, *beNew), transpose(Fi)), out.state.data());
  else
    stateFromSymmetric(symmetricFromState(old), out.state.data());
  std::copy(old + kJ2BackStress, old + kJ2BackStress + 6, out.state.data() + kJ2BackStress);  // zero here
  finishPoint(F, old, r, tr, normE, out);
}

// D = d tau / d b_e^tr on the principal axes (header), then dP/dF by the chain
// d b_e^tr = dF G F^T + F G dF^T and P = tau F^-T (G = C_p^-1, FG = F G).
void J2Plasticity::finiteTangent(const SymmetricEigen& eig, const double* x, const double* n, double theta,
                                 double thetabar, const Mat3& FG, const Mat3& Fi, J2Response& out) const {
  const Mat3& v = eig.vectors;
  double dtdx[3][3], c[3][3];
  for (int A = 0; A < 3; ++A)
    for (int B = 0; B < 3; ++B) {
      const double dtde = kappa_ + 2 * mu_ * theta * ((A == B) - 1.0 / 3.0) - 2 * mu_ * thetabar * n[A] * n[B];
      dtdx[A][B] = dtde / (2 * x[B]);
      c[A][B] = A == B ? 0.0 : 2 * mu_ * theta * logSlope(x[A], x[B]);
    }
  static thread_local double D[3][3][3][3], T[3][3][3][3];
  principalAxesTangent(v, dtdx, c, D);
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int m = 0; m < 3; ++m)
        for (int N = 0; N < 3; ++N)
          T[i][k][m][N] = 2 * (D[i][k][m][0] * FG[0][N] + D[i][k][m][1] * FG[1][N] + D[i][k][m][2] * FG[2][N]);
  for (int i = 0; i < 3; ++i)
    for (int Jc = 0; Jc < 3; ++Jc)
      for (int m = 0; m < 3; ++m)
        for (int N = 0; N < 3; ++N)
          out.A[3 * i + Jc][3 * m + N] = T[i][0][m][N] * Fi[Jc][0] + T[i][1][m][N] * Fi[Jc][1] +
                                         T[i][2][m][N] * Fi[Jc][2] - out.P[i][N] * Fi[Jc][m];
}

double vonMises(const Mat3& s) {
  const double p = trace(s) / 3;
  double q = 0.0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const double d = s[i][j] - (i == j ? p : 0.0);
      q += d * d;
    }
  return std::sqrt(1.5 * q);
}

}  // namespace choc
