// The d'Alembert exact solution of the SDNL111 two-bar impact (docs/verification/benchmarks.md,
// "The exact solution (d'Alembert)"): displacement,
// velocity and contact force at end A of the moving bar AB, as closed forms of time.
//
// With tau = 2L/c and s = (t - t0)/tau (the time since first contact in wave transits):
//   unilateral:  s < 0      A approaches freely at v0;
//                0 <= s < 1 the interface moves at v0/2 (compression in both bars);
//                1 <= s < 2 A moves back at -v0/2 (reflections from B and D meet at A);
//                s >= 2     the contact opens, AB leaves at -v0 for ever.
//   bilateral:   a triangle wave about u = v0 t0 with amplitude |v0| L/c and period
//                8L/c = 4 tau, starting downward (velocity v0/2).
// Contact force (compression positive): Z|v0|/2 with Z = rho c S while in contact;
// bilateral: +Z|v0|/2 on [2k tau, 2(k+1) tau) for even k, -Z|v0|/2 (tension) for odd k.
// At a discontinuity (velocity, force) the right limit is returned.
//
// Against a rigid wall instead of the second bar (SDNV100), with T = L/c: the contact end is
// at rest from t0 to t0 + 2T, then leaves at -v0; the free end moves at v0 until t0 + T,
// then at -v0; the contact force is Z|v0| during [t0, t0 + 2T).
#pragma once

namespace choc {

struct BarImpactParameters {
  double length = 1.0;           // L, each bar [m]
  double waveSpeed = 0.0;        // c [m/s] (bar: sqrt(E/rho); oedometric: see below)
  double impedance = 0.0;        // Z = rho c S [N s/m]
  double impactVelocity = -1.0;  // v0 of bar AB, towards CD (negative) [m/s]
  double contactStart = 0.0;     // t0: 0 in the 1D models, J0/|v0| in the 3D models [s]
  bool bilateral = false;        // modelisation B: the bars are tied from t0 on
  bool rigidWall = false;        // the bar hits a rigid wall (not bilateral)
  bool freeEnd = false;          // with rigidWall: the point is the free end, not the contact end
};

class BarImpactExact {
 public:
  // Throws choc::InputError (file "exact solution") naming the first invalid parameter.
  explicit BarImpactExact(const BarImpactParameters& p);

  // c = sqrt(E/rho): a bar free to contract laterally (nu irrelevant).
  static double barWaveSpeed(double youngsModulus, double density);
  // c_p = sqrt(E(1-nu)/(rho(1+nu)(1-2nu))): lateral displacements blocked.
  static double oedometricWaveSpeed(double youngsModulus, double poissonsRatio, double density);

  // t must be finite and >= 0 (std::invalid_argument otherwise).
  double displacementA(double t) const;  // u_A(t) [m]
  double velocityA(double t) const;      // v_A(t) [m/s]
  double contactForce(double t) const;   // [N], compression positive

  // Z|v0|/2 (Z|v0| against a rigid wall)
  double contactForceMagnitude() const { return (p_.rigidWall ? 1.0 : 0.5) * p_.impedance * absV0(); }
  double peakDisplacement() const;  // max |u_A| over the first contact: |v0| (t0 + L/c)
                                    // (rigid wall: |v0| t0 at the contact end)
  double transitTime() const { return tau_; }       // tau = 2L/c
  double contactStart() const { return p_.contactStart; }
  double contactEnd() const;       // t0 + 2 tau; +infinity when bilateral
  double contactDuration() const;  // 2 tau; +infinity when bilateral
  double period() const { return 4.0 * tau_; }  // 8L/c, the period of the tied bars
  const BarImpactParameters& parameters() const { return p_; }

 private:
  double absV0() const { return p_.impactVelocity < 0 ? -p_.impactVelocity : p_.impactVelocity; }
  double phase(double t) const;  // s = (t - t0)/tau, after checking t

  BarImpactParameters p_;
  double tau_ = 0.0;
};

}  // namespace choc
