// The model's kinematics per block (Model/Blocks/<name>/Strain) and its material law
// (Model/Materials/<name>/Model): which blocks are computed in finite strain, and their linear
// part's stiffness.
#include <algorithm>
#include <chrono>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Resources.hpp"
#include "physics/Model.hpp"

namespace choc {

std::shared_ptr<const FiniteStrainSolid> Model::strainKernel(const ElementBlock& blk, const Teuchos::ParameterList& bp,
                                                             const std::string& materialName,
                                                             const Teuchos::ParameterList& mp) const {
  const std::string strain = bp.get<std::string>("Strain"), law = mp.get<std::string>("Model");
  const std::string path = "Model/Blocks/" + blk.name, lawPath = "Model/Materials/" + materialName + "/Model";
  const bool finite = strain == "finite", linearLaw = law == "linear elastic", plastic = law == "J2 plasticity";
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
  if (fbar && (!finite || (blk.topology != "HEX8" && blk.topology != "QUAD4")))
    throwInput(inputFile_, path + "/Formulation", "F-bar",
               "F-bar is for HEX8 and QUAD4 blocks in finite strain; block '" + blk.name + "' has " + blk.topology +
                   " elements and 'Strain' = '" + strain + "'",
               "set 'Formulation' = 'standard', or 'Strain' = 'finite' on a HEX8 or QUAD4 block");
  if (!finite && !plastic) return nullptr;
  if (plastic && !(mp.get<double>("Yield Stress") > 0))
    throwInput(inputFile_, "Model/Materials/" + materialName + "/Yield Stress",
               format("%g", mp.get<double>("Yield Stress")), "'J2 plasticity' needs the initial yield stress",
               "give 'Yield Stress' > 0 [Pa]");
  try {
    const double E = mp.get<double>("Young's Modulus"), nu = mp.get<double>("Poisson's Ratio");
    if (plastic)
      return std::make_shared<const FiniteStrainSolid>(
          blk.topology, kinematics_,
          std::make_shared<const J2Plasticity>(
              J2Parameters{E, nu, mp.get<double>("Yield Stress"), mp.get<double>("Hardening Modulus")}, finite),
          fbar);
    return std::make_shared<const FiniteStrainSolid>(blk.topology, kinematics_, makeHyperelastic(law, E, nu), fbar);
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile_, plastic ? "Model/Materials/" + materialName : path, "", e.what());
  }
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
