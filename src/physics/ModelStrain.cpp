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
#include "materials/MaterialLaw.hpp"
#include "physics/Model.hpp"

namespace choc {

std::shared_ptr<const FiniteStrainSolid> Model::strainKernel(const ElementBlock& blk, const Teuchos::ParameterList& bp,
                                                             const std::string& materialName,
                                                             const Teuchos::ParameterList& mp) const {
  const std::string strain = bp.get<std::string>("Strain"), lawName = mp.get<std::string>("Model");
  const MaterialLaw& law = materialLaw(lawName);
  const std::string path = "Model/Blocks/" + blk.name, lawPath = "Model/Materials/" + materialName + "/Model";
  const bool finite = strain == "finite", plastic = law.dissipative();
  checkLawKinematics(blk, law, finite, materialName);
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
  if (!finite && law.assembled()) return nullptr;
  if (plastic && onePoint)  // one point per element: the constant-pressure constraint locks plastic flow
    log() << "choc: warning: " << inputFile_ << ": block '" << blk.name << "' is plastic ('" << lawName << "') on "
          << blk.topology << " elements, which lock in plastic flow (the Taylor bar's face spreads to 4.4-4.7 mm "
          << "for 7.2 mm): mesh it with " << (blk.topology == "TET4" ? "TET10" : "TRI6")
          << " elements (gmsh -order 2) or HEX8 / QUAD4 with 'Formulation' = 'F-bar'\n";
  const std::shared_ptr<const MaterialPoint> point =
      law.point(LawInput{inputFile_, "Model/Materials/" + materialName + "/", mp, blk.name}, finite);
  try {
    return std::make_shared<const FiniteStrainSolid>(blk.topology, kinematics_, point, form);
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile_, path, "", e.what());
  }
}

// The block's 'Strain' against the kinematics its material's law runs on (and beams: small-strain
// linear elastic).
void Model::checkLawKinematics(const ElementBlock& blk, const MaterialLaw& law, bool finite,
                               const std::string& materialName) const {
  const std::string path = "Model/Blocks/" + blk.name, lawPath = "Model/Materials/" + materialName + "/Model";
  const std::string strain = finite ? "finite" : "small";
  if (blk.topology == "BEAM2" && finite)
    throwInput(inputFile_, path + "/Strain", strain, "beams (BEAM2) are small-strain in choc",
               "set 'Strain' = 'small' on block '" + blk.name + "'");
  if (blk.topology == "BEAM2" && !law.assembled())
    throwInput(inputFile_, lawPath, law.name(), "beams (BEAM2) are linear elastic in choc (block '" + blk.name + "')",
               "give the beams a 'linear elastic' material");
  if (finite && !law.finiteStrain())
    throwInput(inputFile_, path + "/Strain", strain,
               "material '" + materialName + "' is '" + law.name() + "', a small-strain law",
               "set '" + lawPath + "' = " + law.finiteStrainAlternative());
  if (!finite && !law.smallStrain())
    throwInput(inputFile_, lawPath, law.name(), "a finite-strain law on block '" + blk.name + "', whose 'Strain' is 'small'",
               "set '" + path + "/Strain' = 'finite', or the material's 'Model' = 'linear elastic'");
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
