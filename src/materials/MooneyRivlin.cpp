// 'Mooney-Rivlin': the compressible Mooney-Rivlin rubber, finite strain,
//
//   W = C10 (I1b - 3) + C01 (I2b - 3) + K/2 (J - 1)^2,
//
// I1b = J^(-2/3) I1 and I2b = J^(-4/3) I2 the invariants of the isochoric part of C = F^T F
// (I1 = tr C, I2 = ((tr C)^2 - tr C^2) / 2), J = det F, K the bulk modulus. With a = J^(-2/3),
// C^-1 = Ci,
//   S = 2 C10 a (I - I1/3 Ci) + 2 C01 a^2 (I1 I - C - 2/3 I2 Ci) + K J (J - 1) Ci,
// and the tangent CC = 2 dS/dC (below, term by term). At rest it is the linear elastic material of
// shear modulus mu = 2 (C10 + C01) and bulk modulus K. On an isochoric deformation (J = 1) the
// volumetric term is zero and the stress differences are the incompressible closed forms:
// uniaxial sigma_11 - sigma_22 = 2 (l^2 - 1/l)(C10 + C01 / l), equibiaxial sigma_11 - sigma_33 =
// 2 (l^2 - l^-4)(C10 + C01 l^2), simple shear sigma_12 = 2 gamma (C10 + C01).
#include <cmath>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "input/ParameterSpec.hpp"
#include "materials/Hyperelastic.hpp"
#include "materials/HyperelasticPoint.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {

namespace {

struct MooneyRivlinConstants {
  double c10 = 0.0, c01 = 0.0, bulk = 0.0;
  double shear() const { return 2 * (c10 + c01); }
};

class MooneyRivlin : public HyperelasticMaterial {
 public:
  explicit MooneyRivlin(MooneyRivlinConstants c) : c_(c) {}
  const char* name() const override { return "Mooney-Rivlin"; }
  void respond(const Mat3& C, bool withTangent, StressResponse& out) const override {
    const double detC = positiveDeterminant(C, "Mooney-Rivlin");
    const double J = std::sqrt(detC), a = std::pow(J, -2.0 / 3.0), b = a * a;
    const Mat3 Ci = inverse(C, detC), C2 = multiply(C, C);
    const double I1 = trace(C), I2 = 0.5 * (I1 * I1 - trace(C2));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double d = i == j ? 1.0 : 0.0;
        out.S[i][j] = 2 * c_.c10 * a * (d - I1 / 3 * Ci[i][j]) +
                      2 * c_.c01 * b * (I1 * d - C[i][j] - 2.0 / 3.0 * I2 * Ci[i][j]) + c_.bulk * J * (J - 1) * Ci[i][j];
      }
    out.energy = c_.c10 * (a * I1 - 3) + c_.c01 * (b * I2 - 3) + 0.5 * c_.bulk * (J - 1) * (J - 1);
    if (withTangent) tangent(C, Ci, J, a, I1, I2, out.tangent);
  }

 private:
  // CC = 2 dS/dC, with II(Ci)_IJKL = (Ci_IK Ci_JL + Ci_IL Ci_JK) / 2 = -dCi_IJ/dC_KL and II the
  // symmetric identity:
  //   dS1/dC = 2 C10 a [ -1/3 (I - I1/3 Ci) (x) Ci - 1/3 Ci (x) I + I1/3 II(Ci) ]
  //   dS2/dC = 2 C01 a^2 [ -2/3 (I1 I - C - 2/3 I2 Ci) (x) Ci + I (x) I - II
  //                        - 2/3 Ci (x) (I1 I - C) + 2/3 I2 II(Ci) ]
  //   dS3/dC = K [ (J^2 - J/2) Ci (x) Ci - (J^2 - J) II(Ci) ]
  void tangent(const Mat3& C, const Mat3& Ci, double J, double a, double I1, double I2, Tensor4 out) const {
    const double b = a * a;
    for (int I = 0; I < 3; ++I)
      for (int Jj = 0; Jj < 3; ++Jj)
        for (int K = 0; K < 3; ++K)
          for (int L = 0; L < 3; ++L) {
            const double dIJ = I == Jj, dKL = K == L;
            const double sym = 0.5 * ((I == K && Jj == L) + (I == L && Jj == K));
            const double symCi = 0.5 * (Ci[I][K] * Ci[Jj][L] + Ci[I][L] * Ci[Jj][K]);
            const double t1 = 2 * c_.c10 * a *
                              (-(dIJ - I1 / 3 * Ci[I][Jj]) * Ci[K][L] / 3 - Ci[I][Jj] * dKL / 3 + I1 / 3 * symCi);
            const double t2 = 2 * c_.c01 * b *
                              (-2.0 / 3.0 * (I1 * dIJ - C[I][Jj] - 2.0 / 3.0 * I2 * Ci[I][Jj]) * Ci[K][L] + dIJ * dKL -
                               sym - 2.0 / 3.0 * Ci[I][Jj] * (I1 * dKL - C[K][L]) + 2.0 / 3.0 * I2 * symCi);
            const double t3 = c_.bulk * ((J * J - J / 2) * Ci[I][Jj] * Ci[K][L] - (J * J - J) * symCi);
            out[I][Jj][K][L] = 2 * (t1 + t2 + t3);
          }
  }
  MooneyRivlinConstants c_;
};

const char* const kC10 = "Mooney-Rivlin C10";
const char* const kC01 = "Mooney-Rivlin C01";
const char* const kBulk = "Bulk Modulus";

class MooneyRivlinLaw : public MaterialLaw {
 public:
  const char* name() const override { return "Mooney-Rivlin"; }
  std::string description() const override {
    return "compressible 'Mooney-Rivlin' rubber (W = C10 (I1b - 3) + C01 (I2b - 3) + K/2 (J - 1)^2, I1b and I2b "
           "the isochoric invariants; its own constants, not E and nu),";
  }
  bool smallStrain() const override { return false; }
  bool finiteStrain() const override { return true; }
  bool readsElasticConstants() const override { return false; }
  void declare(Teuchos::ParameterList& mat) const override {
    declareDouble(mat, kC10, 0.0, "'Mooney-Rivlin': C10 [Pa] (required, > 0; shear modulus mu = 2 (C10 + C01))",
                  Range::nonNegative());
    declareDouble(mat, kC01, 0.0, "'Mooney-Rivlin': C01 [Pa] (>= 0; 0: the neo-Hookean rubber)", Range::nonNegative());
    declareDouble(mat, kBulk, 0.0, "'Mooney-Rivlin': the bulk modulus K [Pa] (required, > 0)", Range::nonNegative());
  }
  std::vector<std::string> keysRead(const Teuchos::ParameterList&) const override { return {kC10, kC01, kBulk}; }
  void checkKeys(const LawInput& in) const override {
    for (const char* key : {kC10, kBulk})
      if (!(in.keys.get<double>(key) > 0))
        throwInput(in.file, in.path + key, in.keys.getEntry(key).isDefault() ? "" : format("%g", in.keys.get<double>(key)),
                   in.keys.getEntry(key).isDefault() ? "is missing: 'Mooney-Rivlin' needs it" : "must be > 0",
                   std::string("give '") + key + "' > 0 [Pa]");
  }
  void explainUnread(const LawInput& in, const std::string& key) const override {
    if (key == "Young's Modulus" || key == "Poisson's Ratio")
      throwInput(in.file, in.path + key, format("%g", in.keys.get<double>(key)), "is not a parameter of 'Mooney-Rivlin'",
                 "give its own constants: '" + std::string(kC10) + "', '" + kC01 + "' and '" + kBulk +
                     "' (at rest: mu = 2 (C10 + C01), E = 9 K mu / (3 K + mu))");
  }
  ElasticConstants elasticConstants(const Teuchos::ParameterList& keys) const override {
    const MooneyRivlinConstants c = constants(keys);
    const double mu = c.shear(), K = c.bulk;
    return {9 * K * mu / (3 * K + mu), (3 * K - 2 * mu) / (2 * (3 * K + mu))};
  }
  std::shared_ptr<const MaterialPoint> point(const LawInput& in, bool) const override {
    return hyperelasticPoint(std::make_shared<const MooneyRivlin>(constants(in.keys)));
  }

 private:
  static MooneyRivlinConstants constants(const Teuchos::ParameterList& keys) {
    return {keys.get<double>(kC10), keys.get<double>(kC01), keys.get<double>(kBulk)};
  }
};

}  // namespace

const MaterialLaw& mooneyRivlinLaw() {
  static const MooneyRivlinLaw law;
  return law;
}

}  // namespace choc
