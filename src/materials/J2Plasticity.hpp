// J2 (von Mises) plasticity with isotropic hardening: a pure function of the
// deformation gradient F and the point's committed state, returning the first Piola-Kirchhoff
// stress, its consistent (algorithmic) tangent dP/dF, the new state and the plastic work
// (STYLE.md "Shape of nonlinear physics"). Yield: ||dev tau|| <= sqrt(2/3) sigma_y(alpha, rate, T),
// alpha the equivalent plastic strain, sigma_y a flow-stress law (FlowStress.hpp: linear, a
// flow curve or Johnson-Cook); the flow is associative and isochoric, integrated by backward
// Euler (the radial return: exact for proportional loading). The return's scalar equation
//     2 mu ||e|| - 2 mu dgamma - sqrt(2/3) sigma_y(alpha_n + sqrt(2/3) dgamma, ...) = 0
// is solved in closed form for linear hardening, else by Newton safeguarded by bisection on
// [0, f_trial / 2 mu] (the root is unique there); a return that does not converge throws
// std::domain_error (the caller names the element, the point and the time).
//
// Finite strain (Simo 1992; Simo and Hughes, Computational Inelasticity, ch. 9): the
// multiplicative split F = F_e F_p with the elastic left Cauchy-Green tensor b_e and the
// Hencky (logarithmic) elastic energy
//     W = K/2 (tr eps_e)^2 + mu ||dev eps_e||^2,   eps_e = 1/2 ln b_e,   tau = dW/d eps_e,
// tau the Kirchhoff stress. The trial state b_e^tr = F C_p^-1 F^T (C_p^-1 committed); in the
// principal axes of b_e^tr the exponential map's return is the small-strain radial return
// on the logarithmic strains, and the new C_p^-1 = F^-1 b_e F^-T. The state holds C_p^-1 (I at
// the start) and alpha.
//
// Small strain: eps = sym(F - I) (F - I the displacement gradient), the additive split
// eps = eps_e + eps_p, sigma = K tr(eps_e) I + 2 mu dev(eps_e), P = sigma; the state holds
// eps_p and alpha. Optional linear kinematic hardening (Prager-Ziegler, small strain only): the
// yield surface's centre, the back stress beta (deviatoric, in the state), moves with the flow,
// d beta = 2/3 H_k d eps_p; the yield function and the return take the relative stress
// xi = dev sigma - beta (the return's 2 mu becomes 2 mu + 2/3 H_k, its direction n = xi / ||xi||),
// and the stored energy gains 3/4 ||beta||^2 / H_k (= 1/2 H_k alpha^2 under proportional flow),
// so that the work the balance counts as dissipated is xi : d eps_p >= 0 and the energy stored in
// the back stress comes back on reverse loading.
//
// The tangent is the exact derivative of the return map (the consistent tangent), in closed
// form: on the principal axes dtau_A/d eps_B = K + 2 mu theta (delta_AB - 1/3)
// - 2 mu thetabar n_A n_B, theta = 1 - 2 mu dgamma / ||s_tr||, thetabar = 1 / (1 + H' / 3 mu)
// - (1 - theta) (0 when elastic), H' = d sigma_y / d alpha at the new state (with Johnson-Cook's
// rate term over dt; the temperature is the increment's start's, FlowStress.hpp), and the spin terms 2 mu theta (eps_A - eps_B) / (x_A - x_B)
// between axes (x_A the eigenvalues of b_e^tr), whose limit for equal x is mu theta / x_A.
#pragma once
#include <array>
#include <string>

#include "materials/FlowStress.hpp"
#include "materials/JohnsonCookDamage.hpp"
#include "materials/SymmetricEigen.hpp"
#include "materials/Tensor2.hpp"

namespace choc {

struct J2Parameters {
  double youngsModulus = 0.0, poissonsRatio = 0.0;
  double yieldStress = 0.0;  // sigma_y [Pa] (linear hardening)
  double hardening = 0.0;    // H = d sigma_y / d alpha [Pa] (linear hardening)
  double kinematicHardening = 0.0;  // H_k [Pa]: linear kinematic hardening (small strain only)
  FlowCurve curve;           // when not empty, the flow stress instead of yieldStress and hardening
  bool johnsonCook = false;  // the Johnson-Cook law below instead of both
  JohnsonCookParameters jc;
  JohnsonCookDamageParameters damage;  // Johnson-Cook's cumulative damage, reported (Johnson-Cook only)
};

// The parameters of linear isotropic hardening.
inline J2Parameters linearHardening(double E, double nu, double yieldStress, double hardening) {
  J2Parameters p;
  p.youngsModulus = E, p.poissonsRatio = nu, p.yieldStress = yieldStress, p.hardening = hardening;
  return p;
}

// A point's state: the plastic tensor (C_p^-1 or eps_p: xx yy zz xy yz zx), alpha, the
// last accepted W, P and F (for the increment's dissipated work, below), the temperature and
// the back stress beta (xx yy zz xy yz zx; zero without kinematic hardening) and Johnson-Cook's
// damage D (JohnsonCookDamage.hpp; zero without it).
constexpr int kJ2StateSize = 34;
constexpr int kJ2Alpha = 6, kJ2Energy = 7, kJ2Stress = 8, kJ2Deformation = 17, kJ2Temperature = 26,
              kJ2BackStress = 27, kJ2Damage = 33;

struct J2Response {
  Mat3 P{};                  // first Piola-Kirchhoff stress (small strain: sigma)
  double A[9][9]{};          // dP_iJ / dF_kL at [3 i + J][3 k + L], when asked
  Mat3 cauchy{};             // sigma = tau / det F (small strain: sigma)
  double energy = 0.0;       // the stored elastic energy W per reference volume [J/m^3]
  // This increment's dissipated work per reference volume, by the trapezoidal rule the energy
  // balance measures the external work with: 1/2 (P_n + P) : (F - F_n) - (W - W_n). In small
  // strain it is 1/2 (sigma_n + sigma) : d eps_p >= 0 exactly (W is quadratic); in finite strain
  // it adds, at an elastic point, the trapezoid's O(|dF|^3) error of the Hencky energy.
  double plasticWork = 0.0;
  bool yielded = false;
  std::array<double, kJ2StateSize> state{};  // the state after the increment
};

class J2Plasticity {
 public:
  // Throws std::invalid_argument (naming the value) for E <= 0, nu outside (-1, 0.5),
  // sigma_y <= 0, H < 0 or H_k < 0, H_k > 0 in finite strain, for a flow curve or
  // Johnson-Cook parameters out of range, and for damage without Johnson-Cook's flow stress.
  J2Plasticity(const J2Parameters& p, bool finiteStrain);
  bool finiteStrain() const { return finite_; }
  const J2Parameters& parameters() const { return p_; }
  const FlowStress& flowStress() const { return flow_; }
  // Johnson-Cook's damage is accumulated in the state (kJ2Damage).
  bool hasDamage() const { return damage_.enabled(); }
  double shearModulus() const { return mu_; }
  double bulkModulus() const { return kappa_; }
  // The state of a virgin point.
  std::array<double, kJ2StateSize> initialState() const;
  // The response at F from the committed state `old`. Throws std::domain_error for
  // det F <= 0 in finite strain. With `elasticTangent`, A is the elastic tangent at the trial
  // state (theta = 1, thetabar = 0): the stiffness of a point that unloads, the largest it can
  // show, for the explicit critical step (the consistent tangent of a yielding point is softer).
  // dt: the increment's duration, for a rate-dependent flow stress (0: quasi-static).
  void respond(const Mat3& F, const double* old, bool withTangent, J2Response& out,
               bool elasticTangent = false, double dt = 0.0) const;

 private:
  struct Return {
    double dgamma = 0.0, theta = 1.0, thetabar = 0.0, flowStress = 0.0;
    bool yielded = false;
  };
  // The radial return on the deviatoric trial strain's norm ||e|| (header).
  Return radialReturn(double normE, const double* old, double dt) const;
  double solveReturn(double trial, double f0, const double* old, double dt, FlowStress::Value& at) const;
  void respondFinite(const Mat3& F, const double* old, bool withTangent, bool elastic, double dt,
                     J2Response& out) const;
  // respondFinite without the tangent and without b_e's principal axes (NearScalarLog.hpp):
  // false, nothing done, when b_e is too far from a multiple of I for its series.
  bool respondFiniteBySeries(const Mat3& F, const Mat3& Fi, double J, const Mat3& be, const double* old, double dt,
                             J2Response& out) const;
  void finishFinitePoint(const Mat3& F, const Mat3& Fi, double J, const Mat3& tau, const Mat3* beNew,
                         const double* old, const Return& r, double tr, double normE, J2Response& out) const;
  void respondSmall(const Mat3& F, const double* old, bool withTangent, bool elastic, double dt,
                    J2Response& out) const;
  void finishPoint(const Mat3& F, const double* old, const Return& r, double tr, double normE,
                   J2Response& out, const double* storedEnergy = nullptr) const;
  // D_n + d alpha / eps_f at the new Cauchy stress (JohnsonCookDamage.hpp) into out.state.
  void accumulateDamage(const double* old, double dt, J2Response& out) const;
  void finiteTangent(const SymmetricEigen& eig, const double* x, const double* n, double theta, double thetabar,
                     const Mat3& FG, const Mat3& Fi, J2Response& out) const;
  J2Parameters p_;
  FlowStress flow_;
  JohnsonCookDamage damage_;
  bool finite_;
  double mu_, kappa_;
  double hk_ = 0.0;  // H_k
};

// The von Mises equivalent stress sqrt(3/2) ||dev sigma||.
double vonMises(const Mat3& sigma);

}  // namespace choc
