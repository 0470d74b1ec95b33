// 'Saint Venant-Kirchhoff' and 'neo-Hookean' (Hyperelastic.hpp) as material laws: finite strain,
// Young's modulus and Poisson's ratio only.
#include "core/Errors.hpp"
#include "materials/HyperelasticPoint.hpp"
#include "materials/MaterialLaw.hpp"

namespace choc {

namespace {

class HyperelasticLaw : public MaterialLaw {
 public:
  HyperelasticLaw(const char* name, const char* description) : name_(name), description_(description) {}
  const char* name() const override { return name_; }
  std::string description() const override { return description_; }
  bool smallStrain() const override { return false; }
  bool finiteStrain() const override { return true; }
  std::shared_ptr<const MaterialPoint> point(const LawInput& in, bool) const override {
    const ElasticConstants c = elasticConstants(in.keys);
    try {
      return hyperelasticPoint(makeHyperelastic(name_, c.youngsModulus, c.poissonsRatio));
    } catch (const std::invalid_argument& e) {
      throwInput(in.file, in.path + "Model", name_, e.what());
    }
  }

 private:
  const char* name_;
  const char* description_;
};

}  // namespace

const MaterialLaw& saintVenantKirchhoffLaw() {
  static const HyperelasticLaw law(
      "Saint Venant-Kirchhoff",
      "in finite strain ('Strain' = 'finite'), 'Saint Venant-Kirchhoff' (S = lambda tr(E) I + 2 mu E, E the "
      "Green-Lagrange strain: exact for large rotations, for moderate strains),");
  return law;
}

const MaterialLaw& neoHookeanLaw() {
  static const HyperelasticLaw law("neo-Hookean",
                                   "compressible 'neo-Hookean' (W = mu/2 (I1 - 3) - mu ln J + lambda/2 (ln J)^2; mu "
                                   "and lambda the Lame constants of E and nu),");
  return law;
}

}  // namespace choc
