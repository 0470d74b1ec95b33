// The model's kinematics per block (Model/Blocks/<name>/Strain) and its material law
// (Model/Materials/<name>/Model): which blocks are computed in finite strain, and their linear
// part's stiffness.
#include <algorithm>
#include <chrono>

#include "core/Errors.hpp"
#include "core/Resources.hpp"
#include "physics/Model.hpp"

namespace choc {

std::shared_ptr<const FiniteStrainSolid> Model::strainKernel(const ElementBlock& blk, const Teuchos::ParameterList& bp,
                                                             const std::string& materialName,
                                                             const Teuchos::ParameterList& mp) const {
  const std::string strain = bp.get<std::string>("Strain"), law = mp.get<std::string>("Model");
  const std::string path = "Model/Blocks/" + blk.name;
  const bool finite = strain == "finite", linearLaw = law == "linear elastic";
  if (finite && blk.topology == "BEAM2")
    throwInput(inputFile_, path + "/Strain", strain, "beams (BEAM2) are small-strain in choc",
               "set 'Strain' = 'small' on block '" + blk.name + "'");
  if (finite && linearLaw)
    throwInput(inputFile_, path + "/Strain", strain,
               "material '" + materialName + "' is 'linear elastic', a small-strain law",
               "set 'Model/Materials/" + materialName +
                   "/Model' = 'Saint Venant-Kirchhoff' (the same E and nu in finite strain) or 'neo-Hookean'");
  if (!finite && !linearLaw)
    throwInput(inputFile_, "Model/Materials/" + materialName + "/Model", law,
               "a finite-strain law on block '" + blk.name + "', whose 'Strain' is 'small'",
               "set '" + path + "/Strain' = 'finite', or the material's 'Model' = 'linear elastic'");
  if (!finite) return nullptr;
  try {
    return std::make_shared<const FiniteStrainSolid>(
        blk.topology, kinematics_,
        makeHyperelastic(law, mp.get<double>("Young's Modulus"), mp.get<double>("Poisson's Ratio")));
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile_, path, "", e.what());
  }
}

bool Model::finiteStrain() const {
  return std::any_of(finite_.begin(), finite_.end(), [](const auto& k) { return k != nullptr; });
}

std::string Model::firstFiniteStrainBlock() const {
  for (size_t b = 0; b < finite_.size(); ++b)
    if (finite_[b]) return mesh_.blocks[b].name;
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
