// The model's kinematics per block (Model/Blocks/<name>/Strain) and its material law
// (Model/Materials/<name>/Model): which blocks are computed in finite strain, and their linear
// part's stiffness.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "core/Resources.hpp"
#include "input/XmlInput.hpp"
#include "physics/Model.hpp"

namespace choc {

std::shared_ptr<const FiniteStrainSolid> Model::strainKernel(const ElementBlock& blk, const Teuchos::ParameterList& bp,
                                                             const std::string& materialName,
                                                             const Teuchos::ParameterList& mp) const {
  const std::string strain = bp.get<std::string>("Strain"), law = mp.get<std::string>("Model");
  const std::string path = "Model/Blocks/" + blk.name, lawPath = "Model/Materials/" + materialName + "/Model";
  const bool finite = strain == "finite", linearLaw = law == "linear elastic";
  const bool plastic = law == "J2 plasticity" || law == "Johnson-Cook";
  if (blk.topology == "BEAM2" && finite)
    throwInput(inputFile_, path + "/Strain", strain, "beams (BEAM2) are small-strain in choc",
               "set 'Strain' = 'small' on block '" + blk.name + "'");
  if (blk.topology == "BEAM2" && plastic)
    throwInput(inputFile_, lawPath, law, "beams (BEAM2) are linear elastic in choc (block '" + blk.name + "')",
               "give the beams a 'linear elastic' material");
  if (finite && linearLaw)
    throwInput(inputFile_, path + "/Strain", strain,
               "material '" + materialName + "' is 'linear elastic', a small-strain law",
               "set '" + lawPath + "' = 'Saint Venant-Kirchhoff' (the same E and nu in finite strain) or 'neo-Hookean'");
  if (!finite && !linearLaw && !plastic)
    throwInput(inputFile_, lawPath, law, "a finite-strain law on block '" + blk.name + "', whose 'Strain' is 'small'",
               "set '" + path + "/Strain' = 'finite', or the material's 'Model' = 'linear elastic'");
  const bool fbar = bp.get<std::string>("Formulation") == "F-bar";
  const bool onePoint = blk.topology == "TET4" || blk.topology == "TRI3";
  if (fbar && (!finite || onePoint))
    throwInput(inputFile_, path + "/Formulation", "F-bar",
               "F-bar is for blocks in finite strain of elements with several points (HEX8, HEX20, TET10, QUAD4, "
               "QUAD8, TRI6); block '" + blk.name + "' has " + blk.topology + " elements and 'Strain' = '" + strain + "'",
               onePoint ? "mesh the block with " + std::string(blk.topology == "TET4" ? "TET10" : "TRI6") +
                              " elements (gmsh -order 2), or set 'Formulation' = 'standard'"
                        : "set 'Strain' = 'finite', or 'Formulation' = 'standard'");
  ElementFormulation form{fbar, bp.get<std::string>("Formulation") == "one-point",
                          bp.get<double>("Hourglass Coefficient")};
  if (form.onePoint) checkOnePoint(blk, finite || plastic);
  if (mp.get<std::string>("Damage") != "none" && law != "Johnson-Cook")
    throwInput(inputFile_, "Model/Materials/" + materialName + "/Damage", mp.get<std::string>("Damage"),
               "Johnson-Cook damage needs the Johnson-Cook flow stress (its reference rate and temperatures); the "
               "material's 'Model' is '" + law + "'",
               "set 'Model' = 'Johnson-Cook', or 'Damage' = 'none'");
  if (!finite && !plastic) return nullptr;
  if (plastic && onePoint)  // one point per element: the constant-pressure constraint locks plastic flow
    log() << "choc: warning: " << inputFile_ << ": block '" << blk.name << "' is plastic ('" << law << "') on "
          << blk.topology << " elements, which lock in plastic flow (the Taylor bar's face spreads to 4.4-4.7 mm "
          << "for 7.2 mm): mesh it with " << (blk.topology == "TET4" ? "TET10" : "TRI6")
          << " elements (gmsh -order 2) or HEX8 / QUAD4 with 'Formulation' = 'F-bar'\n";
  if (plastic && finite && mp.get<double>("Kinematic Hardening Modulus") > 0)
    throwInput(inputFile_, "Model/Materials/" + materialName + "/Kinematic Hardening Modulus",
               format("%g", mp.get<double>("Kinematic Hardening Modulus")),
               "kinematic hardening is small-strain only; block '" + blk.name + "' has 'Strain' = 'finite'",
               "set the block's 'Strain' = 'small', or 'Kinematic Hardening Modulus' = 0");
  try {
    const double E = mp.get<double>("Young's Modulus"), nu = mp.get<double>("Poisson's Ratio");
    SolidMaterial m;
    if (plastic)
      m.plastic = std::make_shared<const J2Plasticity>(plasticParameters(materialName, mp), finite);
    else
      m.elastic = makeHyperelastic(law, E, nu);
    return std::make_shared<const FiniteStrainSolid>(blk.topology, kinematics_, m, form);
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile_, plastic ? "Model/Materials/" + materialName : path, "", e.what());
  }
}

// 'Formulation' = 'one-point': HEX8 in 3D or QUAD4 in plane strain, on a block the element-by-element
// kernel computes (finite strain or plastic).
void Model::checkOnePoint(const ElementBlock& blk, bool elementByElement) const {
  const std::string path = "Model/Blocks/" + blk.name + "/Formulation";
  const bool fits = (blk.topology == "HEX8" && kinematics_ == Kinematics::ThreeD) ||
                    (blk.topology == "QUAD4" && kinematics_ == Kinematics::PlaneStrain);
  if (!fits)
    throwInput(inputFile_, path, "one-point",
               "one-point integration with hourglass control is for HEX8 in 3D and QUAD4 in plane strain; block '" +
                   blk.name + "' has " + blk.topology + " elements" +
                   (kinematics_ == Kinematics::Axisymmetric ? " (axisymmetric)" : ""),
               blk.topology == "TET4" || blk.topology == "TRI3"
                   ? "mesh the block with " + std::string(blk.topology == "TET4" ? "HEX8" : "QUAD4") + " elements, or " +
                         (blk.topology == "TET4" ? "TET10" : "TRI6") + " elements with 'Formulation' = 'F-bar'"
                   : "set 'Formulation' = 'F-bar' (locking-free on every element with several points) or 'standard'");
  if (!elementByElement)
    throwInput(inputFile_, path, "one-point",
               "block '" + blk.name + "' is small-strain linear elastic (an assembled stiffness, fully integrated)",
               "set 'Strain' = 'finite' (and a hyperelastic material), or 'Formulation' = 'standard'");
}

namespace {

JohnsonCookDamageParameters damageParameters(const Teuchos::ParameterList& mp) {
  JohnsonCookDamageParameters d;
  d.enabled = mp.get<std::string>("Damage") == "Johnson-Cook";
  d.D1 = mp.get<double>("Johnson-Cook D1"), d.D2 = mp.get<double>("Johnson-Cook D2");
  d.D3 = mp.get<double>("Johnson-Cook D3"), d.D4 = mp.get<double>("Johnson-Cook D4");
  d.D5 = mp.get<double>("Johnson-Cook D5");
  return d;
}

}  // namespace

// A 'J2 plasticity' or 'Johnson-Cook' material's parameters (J2Plasticity checks their ranges).
J2Parameters Model::plasticParameters(const std::string& materialName, const Teuchos::ParameterList& mp) const {
  const std::string path = "Model/Materials/" + materialName + "/";
  J2Parameters p = linearHardening(mp.get<double>("Young's Modulus"), mp.get<double>("Poisson's Ratio"),
                                   mp.get<double>("Yield Stress"), mp.get<double>("Hardening Modulus"));
  p.kinematicHardening = mp.get<double>("Kinematic Hardening Modulus");
  if (mp.get<std::string>("Model") == "Johnson-Cook") {
    p.johnsonCook = true;
    JohnsonCookParameters& jc = p.jc;
    jc.A = mp.get<double>("Johnson-Cook A"), jc.B = mp.get<double>("Johnson-Cook B");
    jc.n = mp.get<double>("Johnson-Cook n"), jc.C = mp.get<double>("Johnson-Cook C");
    jc.referenceRate = mp.get<double>("Reference Strain Rate"), jc.m = mp.get<double>("Johnson-Cook m");
    jc.referenceTemperature = mp.get<double>("Reference Temperature");
    jc.meltingTemperature = mp.get<double>("Melting Temperature");
    jc.initialTemperature = mp.get<double>("Initial Temperature");
    jc.specificHeat = mp.get<double>("Specific Heat");
    jc.taylorQuinney = mp.get<double>("Taylor-Quinney Coefficient");
    jc.density = mp.get<double>("Density");
    p.damage = damageParameters(mp);
    return p;
  }

  const std::string curve = mp.get<std::string>("Flow Curve");
  if (curve.empty()) {
    if (!(p.yieldStress > 0))
      throwInput(inputFile_, path + "Yield Stress", format("%g", p.yieldStress),
                 "'J2 plasticity' needs the initial yield stress", "give 'Yield Stress' > 0 [Pa], or a 'Flow Curve'");
    return p;
  }
  if (p.yieldStress > 0 || p.hardening > 0)
    throwInput(inputFile_, path + "Flow Curve", curve, "a flow curve and 'Yield Stress'/'Hardening Modulus' are both given",
               "give one of them");
  std::istringstream in(curve);
  std::string token;
  std::vector<double> numbers;
  while (in >> token) {
    double v = 0;
    if (!parseDecimal(token, v) || !std::isfinite(v))
      throwInput(inputFile_, path + "Flow Curve", curve, "'" + token + "' is not a number",
                 "give pairs 'plastic_strain stress [Pa]'");
    numbers.push_back(v);
  }
  if (numbers.empty() || numbers.size() % 2 != 0)
    throwInput(inputFile_, path + "Flow Curve", curve, "the curve has " + std::to_string(numbers.size()) + " numbers",
               "give pairs 'plastic_strain stress [Pa]', the first at plastic strain 0");
  for (size_t i = 0; i < numbers.size(); i += 2) {
    p.curve.strain.push_back(numbers[i]);
    p.curve.stress.push_back(numbers[i + 1]);
  }
  return p;
}

bool Model::hasOnePointBlocks() const {
  return std::any_of(finite_.begin(), finite_.end(), [](const auto& k) { return k && k->onePoint(); });
}

bool Model::finiteStrain() const {
  return std::any_of(finite_.begin(), finite_.end(), [](const auto& k) { return k != nullptr; });
}

std::string Model::firstFiniteStrainBlock() const {
  for (size_t b = 0; b < finite_.size(); ++b)
    if (finite_[b] && finite_[b]->finiteKinematics()) return mesh_.blocks[b].name;
  return "";
}

std::string Model::firstPlasticBlock() const {
  for (size_t b = 0; b < finite_.size(); ++b)
    if (finite_[b] && finite_[b]->plastic()) return mesh_.blocks[b].name;
  return "";
}

RCP<const CrsMatrix> Model::smallStrainStiffness() {
  std::vector<char> skip(finite_.size());
  for (size_t b = 0; b < finite_.size(); ++b) skip[b] = finite_[b] != nullptr;
  const auto start = std::chrono::steady_clock::now();
  RCP<const CrsMatrix> K = assembler_->stiffnessWithout(skip, springs_, stiffness()->getCrsGraph());
  logPhase(*comm_, "small-strain blocks' stiffness",
           std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return K;
}

}  // namespace choc
