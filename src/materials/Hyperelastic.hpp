// Hyperelastic materials of finite-strain solids: pure functions of the right Cauchy-Green
// tensor C = F^T F (no mesh, no vector, no state), returning the strain-energy density W per
// reference volume, the second Piola-Kirchhoff stress S = 2 dW/dC and, when asked, the
// material tangent CC_IJKL = dS_IJ/dE_KL = 2 dS_IJ/dC_KL (E = (C - I)/2, the Green-Lagrange
// strain). Both materials take the Lame constants of the given E and nu,
//   mu = E / (2 (1 + nu)),  lambda = E nu / ((1 + nu) (1 - 2 nu)),
// so that at small strain they are the linear elastic material with those constants.
//
//   Saint Venant-Kirchhoff  W = lambda/2 (tr E)^2 + mu E:E,
//                           S = lambda tr(E) I + 2 mu E,   CC = lambda I(x)I + 2 mu II.
//     Linear in E: large rotations are exact, but it softens without bound in compression
//     (W stays finite as J -> 0); use it for moderate strains.
//   neo-Hookean (compressible)
//                           W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2,
//                           I1 = tr C, J = det F = sqrt(det C),
//                           S = mu (I - C^-1) + lambda ln J C^-1,
//                           CC = lambda C^-1 (x) C^-1 + 2 (mu - lambda ln J) II(C^-1),
//     II(C^-1)_IJKL = (C^-1_IK C^-1_JL + C^-1_IL C^-1_JK) / 2.  W -> infinity as J -> 0.
#pragma once
#include <memory>
#include <string>

#include "materials/Tensor2.hpp"

namespace choc {

// A fourth-order tensor with the minor symmetries, stored in full.
using Tensor4 = double[3][3][3][3];

struct StressResponse {
  double energy = 0.0;  // W [J/m^3 of reference volume]
  Mat3 S{};             // second Piola-Kirchhoff stress [Pa]
  Tensor4 tangent{};    // dS/dE [Pa], filled when asked
};

class HyperelasticMaterial {
 public:
  virtual ~HyperelasticMaterial() = default;
  virtual const char* name() const = 0;
  // Throws std::domain_error when C is not positive definite enough for the model (det C <= 0
  // for the neo-Hookean material).
  virtual void respond(const Mat3& C, bool withTangent, StressResponse& out) const = 0;
};

// The two models by their input names ("Saint Venant-Kirchhoff", "neo-Hookean"); throws
// std::invalid_argument for another name or E <= 0, nu outside (-1, 0.5).
std::shared_ptr<const HyperelasticMaterial> makeHyperelastic(const std::string& model, double youngsModulus,
                                                             double poissonsRatio);

// The cauchy stress sigma = F S F^T / det F.
Mat3 cauchyStress(const Mat3& F, const Mat3& S);

// det C, or std::domain_error "<law> material: det C = ... <= 0 (an inverted or collapsed point)"
// for a law whose energy is undefined there.
double positiveDeterminant(const Mat3& C, const char* law);

}  // namespace choc
