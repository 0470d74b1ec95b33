// The flow stress of J2 plasticity, sigma_y(alpha, rate, T): the isotropic hardening laws.
//
//   linear          sigma_y = sigma_0 + H alpha
//   flow curve      sigma_y piecewise linear in alpha through the points (alpha_i, sigma_i),
//                   alpha_0 = 0, constant beyond the last point
//   Johnson-Cook    sigma_y = (A + B alpha^n) (1 + C ln(max(rate / rate_0, 1)))
//                             (1 - T*^m),   T* = (T - T_0) / (T_m - T_0) clamped to [0, 1]
//
// alpha the equivalent plastic strain, rate = d alpha / dt over the increment (below rate_0,
// and when the increment has no duration, the rate factor is 1: the quasi-static law), T the
// temperature. Johnson-Cook's adiabatic heating: the increment's plastic work sigma_y d alpha
// (sigma_y the increment's flow stress) raises the point's temperature by chi sigma_y d alpha /
// (rho c) (chi the Taylor-Quinney coefficient, the share of the work that becomes heat): never
// negative, nothing at a point that does not yield. Used from the next increment on (the temperature is explicit in
// the return map: the usual staggering in impact codes, whose steps are far shorter than the
// heating's time scale).
//
// Every law is non-decreasing in alpha and in the rate at a fixed temperature, so the radial
// return's scalar equation has exactly one root (J2Plasticity).
#pragma once
#include <string>
#include <vector>

namespace choc {

// A piecewise-linear flow curve: the equivalent plastic strain (first 0, increasing) and the flow
// stress there [Pa] (first > 0, non-decreasing).
struct FlowCurve {
  std::vector<double> strain, stress;
};

struct JohnsonCookParameters {
  double A = 0.0, B = 0.0, n = 1.0, C = 0.0;  // [Pa], [Pa], [-], [-]
  double referenceRate = 1.0;                  // rate_0 [1/s]
  double m = 1.0;                              // thermal softening exponent [-]
  double referenceTemperature = 20.0, meltingTemperature = 0.0, initialTemperature = 20.0;  // T_0, T_m, T(t=0)
  double specificHeat = 0.0;                   // c [J/(kg K)]
  double taylorQuinney = 0.9;                  // chi [-]
  double density = 0.0;                        // rho [kg/m^3]
};

// Johnson-Cook's rate and temperature terms, shared by the flow stress and the damage
// (JohnsonCookDamage.hpp): ln(rate / rate_0) for the plastic increment dalpha over dt, 0 below
// rate_0 or without duration; T* = (T - T_0) / (T_m - T_0) clamped to [0, 1].
double johnsonCookLogRate(const JohnsonCookParameters& p, double dalpha, double dt);
double johnsonCookHomologous(const JohnsonCookParameters& p, double temperature);

class FlowStress {
 public:
  static FlowStress linear(double yieldStress, double hardening);
  // Both throw std::invalid_argument naming the parameter and the value that is out of range.
  static FlowStress curve(const FlowCurve& curve);
  static FlowStress johnsonCook(const JohnsonCookParameters& p);

  struct Value {
    double stress = 0.0;  // sigma_y [Pa]
    double slope = 0.0;   // d sigma_y / d dalpha (the hardening and, over dt, the rate's) [Pa]
  };
  // sigma_y after a plastic increment dalpha from alphaOld over dt (dt <= 0: no rate effect) at
  // the temperature T; with dalpha = 0 the yield stress of the point as it stands.
  Value at(double alphaOld, double dalpha, double dt, double temperature) const;
  bool isLinear() const { return kind_ == Kind::Linear; }
  double linearHardening() const { return hardening_; }
  // The temperature rise per unit of plastic work per reference volume, chi / (rho c) [K m^3/J]
  // (0: no heating), and a virgin point's temperature (0 for the laws without temperature).
  double heatPerWork() const { return heatPerWork_; }
  double initialTemperature() const { return kind_ == Kind::JohnsonCook ? jc_.initialTemperature : 0.0; }
  bool hasTemperature() const { return kind_ == Kind::JohnsonCook; }
  // Where the flow stress vanishes (Johnson-Cook's T_m; +infinity for the other laws).
  double meltingTemperature() const;
  // Johnson-Cook at T: the thermal factor 1 - T*^m at most kMelted (the point has lost 99 % of its
  // strength; the heating, chi sigma_y d alpha / (rho c), only approaches T_m itself).
  static constexpr double kMelted = 0.01;
  bool melted(double temperature) const;
  std::string describe() const;

 private:
  enum class Kind { Linear, Curve, JohnsonCook };
  Kind kind_ = Kind::Linear;
  double yield_ = 0.0, hardening_ = 0.0, heatPerWork_ = 0.0;
  FlowCurve curve_;
  JohnsonCookParameters jc_;
};

}  // namespace choc
