// Saint Venant-Kirchhoff and compressible neo-Hookean responses (formulas in the header).
#include "materials/Hyperelastic.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace choc {

namespace {

struct Lame {
  double mu, lambda;
};

Lame lameConstants(const std::string& model, double E, double nu) {
  if (!(E > 0) || !(nu > -1.0 && nu < 0.5)) {
    std::ostringstream msg;
    msg << model << " material: needs Young's modulus > 0 and Poisson's ratio in (-1, 0.5), got E = " << E
        << ", nu = " << nu;
    throw std::invalid_argument(msg.str());
  }
  return {E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))};
}

// out = a A(x)A + b II(B): a A_IJ A_KL + b (B_IK B_JL + B_IL B_JK) / 2.
void isotropicTangent(double a, const Mat3& A, double b, const Mat3& B, Tensor4 out) {
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J)
      for (int K = 0; K < 3; ++K)
        for (int L = 0; L < 3; ++L)
          out[I][J][K][L] = a * A[I][J] * A[K][L] + b * 0.5 * (B[I][K] * B[J][L] + B[I][L] * B[J][K]);
}

class SaintVenantKirchhoff : public HyperelasticMaterial {
 public:
  explicit SaintVenantKirchhoff(Lame l) : l_(l) {}
  const char* name() const override { return "Saint Venant-Kirchhoff"; }
  void respond(const Mat3& C, bool withTangent, StressResponse& out) const override {
    Mat3 E = C;
    for (int i = 0; i < 3; ++i) E[i][i] -= 1.0;
    for (auto& row : E)
      for (double& v : row) v *= 0.5;
    const double tr = trace(E);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.S[i][j] = 2 * l_.mu * E[i][j] + (i == j ? l_.lambda * tr : 0.0);
    out.energy = 0.5 * l_.lambda * tr * tr + l_.mu * contract(E, E);
    if (withTangent) isotropicTangent(l_.lambda, identity3(), 2 * l_.mu, identity3(), out.tangent);
  }

 private:
  Lame l_;
};

class NeoHookean : public HyperelasticMaterial {
 public:
  explicit NeoHookean(Lame l) : l_(l) {}
  const char* name() const override { return "neo-Hookean"; }
  void respond(const Mat3& C, bool withTangent, StressResponse& out) const override {
    const double detC = positiveDeterminant(C, "neo-Hookean");
    const double lnJ = 0.5 * std::log(detC);
    const Mat3 Ci = inverse(C, detC);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.S[i][j] = (i == j ? l_.mu : 0.0) + (l_.lambda * lnJ - l_.mu) * Ci[i][j];
    out.energy = 0.5 * l_.mu * (trace(C) - 3) - l_.mu * lnJ + 0.5 * l_.lambda * lnJ * lnJ;
    if (withTangent) isotropicTangent(l_.lambda, Ci, 2 * (l_.mu - l_.lambda * lnJ), Ci, out.tangent);
  }

 private:
  Lame l_;
};

}  // namespace

std::shared_ptr<const HyperelasticMaterial> makeHyperelastic(const std::string& model, double youngsModulus,
                                                             double poissonsRatio) {
  if (model == "Saint Venant-Kirchhoff")
    return std::make_shared<SaintVenantKirchhoff>(lameConstants(model, youngsModulus, poissonsRatio));
  if (model == "neo-Hookean")
    return std::make_shared<NeoHookean>(lameConstants(model, youngsModulus, poissonsRatio));
  throw std::invalid_argument("unknown hyperelastic model '" + model +
                              "'; valid: 'Saint Venant-Kirchhoff', 'neo-Hookean'");
}

double positiveDeterminant(const Mat3& C, const char* law) {
  const double detC = determinant(C);
  if (!(detC > 0)) {
    std::ostringstream msg;
    msg << law << " material: det C = " << detC << " <= 0 (an inverted or collapsed point)";
    throw std::domain_error(msg.str());
  }
  return detC;
}

Mat3 cauchyStress(const Mat3& F, const Mat3& S) {
  Mat3 s = multiply(multiply(F, S), transpose(F));
  const double J = determinant(F);
  for (auto& row : s)
    for (double& v : row) v /= J;
  return s;
}

}  // namespace choc
