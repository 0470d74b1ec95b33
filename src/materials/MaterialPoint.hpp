// What a material law is to an element: the response of one quadrature point to its
// deformation gradient F and its committed state, and what the point reports. Every law
// (linear elastic, Saint Venant-Kirchhoff, neo-Hookean, Mooney-Rivlin, J2 plasticity,
// Johnson-Cook) implements it; an element never reads a law's state layout (MaterialLaw.hpp
// says how a law is chosen and which keys it reads).
//
//   response   P = dW/dF, the first Piola-Kirchhoff stress (small strain: sigma at
//              eps = sym(F - I)), and A = dP/dF (small strain: dsigma/deps) when asked;
//   state      stateSize() numbers per point: `old` the committed state, `next` the new one
//              (the caller commits it when the step is accepted; stateless laws ignore both);
//   report     the Cauchy stress and stored energy a point shows, and the law's named
//              element fields, each averaged over the element by volume.
#pragma once
#include <string>
#include <vector>

#include "materials/Tensor2.hpp"

namespace choc {

// What the element asks of a point.
struct PointRequest {
  bool tangent = false;         // fill PointResponse::A
  bool elasticTangent = false;  // A at the trial state (an unloading point: the explicit critical step)
  double dt = 0.0;              // the increment's duration (a rate-dependent law; 0: quasi-static)
};

struct PointResponse {
  Mat3 P{};                 // first Piola-Kirchhoff stress (small strain: sigma)
  double A[9][9]{};         // dP_iJ / dF_kL at [3 i + J][3 k + L], when asked
  double energy = 0.0;      // stored energy W per reference volume [J/m^3]
  double dissipated = 0.0;  // this increment's dissipated work per reference volume [J/m^3]
};

class MaterialPoint {
 public:
  virtual ~MaterialPoint() = default;
  virtual const char* name() const = 0;
  // Finite-strain kinematics (F itself); false: small strain, P = sigma(sym(F - I)), no det F check.
  virtual bool finiteStrain() const { return true; }
  // Whether the law dissipates (a return map: the Newton line search and the balance's dissipation).
  virtual bool dissipative() const { return false; }
  // The state's numbers per point and their values at a virgin point.
  virtual int stateSize() const { return 0; }
  virtual void initialState(double* /*state*/) const {}
  // dS_11/dE_11 at F = I (lambda + 2 mu): the size of the stress per unit of strain.
  virtual double modulus() const = 0;
  // The response at F from the committed state `old` (virgin when null); the new state into
  // `next` when not null. Throws std::domain_error where the law cannot take F (det F <= 0).
  virtual void respond(const Mat3& F, const double* old, double* next, const PointRequest& request,
                       PointResponse& out) const = 0;

  // A law with state reports what its state recorded at the last accepted step (no F needed):
  // then recordedCauchy and recordedEnergy give it; otherwise the element evaluates at F.
  virtual bool reportsState() const { return false; }
  virtual Mat3 recordedCauchy(const double* /*state*/) const { return {}; }
  virtual double recordedEnergy(const double* /*state*/) const { return 0.0; }
  // The law's element fields (Exodus element variables beside the stress and energy density),
  // and one point's share of their element averages: sums[k] += w value_k.
  virtual std::vector<std::string> fieldNames() const { return {}; }
  virtual void addFields(const double* /*state*/, const Mat3& /*cauchy*/, double /*w*/, double* /*sums*/) const {}

  // Alarms the run reports once: a point's damage D (failure predicted at D >= 1) and a point
  // that reached its melting temperature (0 and false for laws without them).
  virtual bool hasDamage() const { return false; }
  virtual double damage(const double* /*state*/) const { return 0.0; }
  virtual bool hasTemperature() const { return false; }
  virtual bool melted(const double* /*state*/) const { return false; }
};

// The Cauchy stress P F^T / det F (small strain: P itself).
Mat3 cauchyFromFirstPiola(const Mat3& P, const Mat3& F, bool finiteStrain);

}  // namespace choc
