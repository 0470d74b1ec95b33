// 'linear elastic': isotropic Hooke's law, sigma = lambda tr(eps) I + 2 mu eps, on small-strain
// blocks, whose stiffness is assembled once (fem/SolidElement). Its material point (the same law
// at a point, P = sigma(sym(F - I)), A = dsigma/deps) serves the element-by-element kernels.
#include "core/Errors.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {

namespace {

class LinearElasticPoint : public MaterialPoint {
 public:
  LinearElasticPoint(double E, double nu) : mu_(E / (2 * (1 + nu))), lambda_(E * nu / ((1 + nu) * (1 - 2 * nu))) {}
  const char* name() const override { return "linear elastic"; }
  bool finiteStrain() const override { return false; }
  double modulus() const override { return lambda_ + 2 * mu_; }
  void respond(const Mat3& F, const double*, double*, const PointRequest& request, PointResponse& out) const override {
    Mat3 eps;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) eps[i][j] = 0.5 * (F[i][j] + F[j][i]) - (i == j ? 1.0 : 0.0);
    const double tr = trace(eps);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) out.P[i][j] = 2 * mu_ * eps[i][j] + (i == j ? lambda_ * tr : 0.0);
    out.energy = 0.5 * lambda_ * tr * tr + mu_ * contract(eps, eps);
    out.dissipated = 0.0;
    if (!request.tangent) return;
    for (int i = 0; i < 3; ++i)  // d sigma_iJ / dF_kL = lambda d_iJ d_kL + mu (d_ik d_JL + d_iL d_Jk)
      for (int J = 0; J < 3; ++J)
        for (int k = 0; k < 3; ++k)
          for (int L = 0; L < 3; ++L)
            out.A[3 * i + J][3 * k + L] = (i == J && k == L ? lambda_ : 0.0) + (i == k && J == L ? mu_ : 0.0) +
                                          (i == L && J == k ? mu_ : 0.0);
  }

 private:
  double mu_, lambda_;
};

class LinearElasticLaw : public MaterialLaw {
 public:
  const char* name() const override { return "linear elastic"; }
  std::string description() const override {
    return "'linear elastic' (small strain: blocks with 'Strain' = 'small');";
  }
  bool smallStrain() const override { return true; }
  bool finiteStrain() const override { return false; }
  bool assembled() const override { return true; }
  std::string finiteStrainAlternative() const override {
    return "'Saint Venant-Kirchhoff' (the same E and nu in finite strain) or 'neo-Hookean'";
  }
  std::shared_ptr<const MaterialPoint> point(const LawInput& in, bool) const override {
    const ElasticConstants c = elasticConstants(in.keys);
    return std::make_shared<LinearElasticPoint>(c.youngsModulus, c.poissonsRatio);
  }
};

}  // namespace

const MaterialLaw& linearElasticLaw() {
  static const LinearElasticLaw law;
  return law;
}

}  // namespace choc
