// How a material law enters choc: its name (the value of Model/Materials/<name>/Model), the
// kinematics it runs on, the keys it reads (each law declares only its own), and its material
// point (MaterialPoint.hpp) built from them. Every law is listed once in MaterialLaws.def.
//
// Every material has 'Density' and 'Model'; 'Young's Modulus' and 'Poisson's Ratio' are declared
// once for the laws that read them (readsElasticConstants). A key the chosen law does not read is
// an input error (an elastic answer where plasticity was asked for must not look right), and a
// key it requires that was left out is reported as missing.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "materials/MaterialPoint.hpp"

namespace choc {

// A material's keys and where they come from, for a law's messages and its builder.
struct LawInput {
  std::string file;                    // the input file
  std::string path;                    // "Model/Materials/<name>/"
  const Teuchos::ParameterList& keys;  // validated, defaults filled in
  std::string block = "";              // the block the point is built for ("" when checking keys)
};

// The small-strain elastic constants of a law at rest: the block's mass and linear stiffness
// (small-strain blocks; Rayleigh damping and frequency bounds at u = 0) use them.
struct ElasticConstants {
  double youngsModulus = 0.0, poissonsRatio = 0.0;
};

class MaterialLaw {
 public:
  virtual ~MaterialLaw() = default;
  virtual const char* name() const = 0;
  // Its sentence in the documentation of the 'Model' key.
  virtual std::string description() const = 0;
  // The kinematics it runs on ('Strain' = 'small' / 'finite'); an assembled law (linear elastic)
  // is a small-strain stiffness assembled once, without material points.
  virtual bool smallStrain() const = 0;
  virtual bool finiteStrain() const = 0;
  virtual bool assembled() const { return false; }
  virtual bool dissipative() const { return false; }
  // Where a block in finite strain should go when this law is small-strain only (the fix of the
  // refusal: another law's name and why).
  virtual std::string finiteStrainAlternative() const { return "a finite-strain law"; }
  virtual bool readsElasticConstants() const { return true; }
  // Declares the keys only this law reads on Model/Materials/<any name>.
  virtual void declare(Teuchos::ParameterList& /*materials*/) const {}
  // Every key of its own it reads with these keys (some are read only under a switch).
  virtual std::vector<std::string> keysRead(const Teuchos::ParameterList& /*keys*/) const { return {}; }
  // Throws InputError for a required key left out, or a key it declares but does not read with
  // these keys (naming the switch). The registry checks the elastic constants.
  virtual void checkKeys(const LawInput& /*in*/) const {}
  // A key this law does not read was given: throws InputError with a hint of its own, or returns.
  virtual void explainUnread(const LawInput& /*in*/, const std::string& /*key*/) const {}
  // A key this law reads was given to a material of law `other`: throws InputError with its own
  // message, returns true when the value is harmless there (a switch set to 'none'), or false
  // (the registry then says which laws read it).
  virtual bool explainForeign(const LawInput& /*in*/, const std::string& /*key*/, const std::string& /*other*/) const {
    return false;
  }
  virtual ElasticConstants elasticConstants(const Teuchos::ParameterList& keys) const;
  // Its point for a block of that kinematics (null for an assembled law). Throws InputError
  // naming the key at fault.
  virtual std::shared_ptr<const MaterialPoint> point(const LawInput& in, bool finiteStrain) const = 0;
};

// Every law, in the order of MaterialLaws.def.
const std::vector<const MaterialLaw*>& materialLaws();
// The law of a 'Model' value (validated beforehand: throws std::out_of_range for another).
const MaterialLaw& materialLaw(const std::string& name);
// Declares Density, Model, the elastic constants and every law's keys on Model/Materials.
void declareMaterialLaws(Teuchos::ParameterList& materials);
// Checks a material's keys against its law (the header's rules); throws InputError.
void checkMaterialKeys(const std::string& file, const std::string& materialName, const Teuchos::ParameterList& mp);

}  // namespace choc
