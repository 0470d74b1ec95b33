#include "contact/ContactParameters.hpp"

#include "core/DidYouMean.hpp"
#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

void declareContactParameters(Teuchos::ParameterList& p) {
  ParameterList& ct = declareSublist(p, "Contact", "unilateral contact between side sets");
  declareChoice(ct, "Method", "None", {"None", "Lagrange", "Penalty", "Continuous"},
                "Lagrange: multipliers with an active set (CONTRAINTE); Penalty: E_N per slave "
                "node (PENALISATION); Continuous: augmented Lagrangian with pressure unknowns "
                "(CONTINUE)");
  declareDouble(ct, "Penalty Stiffness", 1e10, "E_N [N/m] per slave node (Penalty)", Range::positive());
  declareDouble(ct, "Augmentation Coefficient", 1e10,
                "c [N/m] of the augmented pressure lambda - c g (Continuous)", Range::positive());
  declareDouble(ct, "Gap Tolerance", 1e-12,
                "penetration [m] above which an inactive node enters the active set "
                "(Lagrange, Continuous)",
                Range::nonNegative());
  declareInt(ct, "Maximum Active Set Iterations", 20,
             "Newton solves per step while the active set changes", Range::atLeast(1));
  ParameterList& pr = declareNamedSublists(ct, "Pairs", "contact pairs, by name");
  declareRequiredString(pr, "Master Side Set", "QUAD4 faces (HEX8 sides), outward normal");
  declareRequiredString(pr, "Slave Side Set", "faces whose nodes are the slave nodes");
  declareDouble(pr, "Search Distance", 1e-3, "largest initial |gap| of a pairing [m]", Range::positive());
  declareChoice(p, "Contact Mass", "standard", {"standard", "redistributed"},
                "standard: the blocks' mass matrices as they are; redistributed: the nodes of the "
                "contact pairs' master and slave side sets carry no mass, each element touching "
                "them has its mass moved onto its other nodes (element mass kept in every "
                "direction; Khenous, Laborde, Renard 2008). Removes the chatter of implicit "
                "schemes with exactly enforced contact (Lagrange, Continuous) at weak numerical "
                "damping, and the average-acceleration rule then keeps the energy through "
                "impacts; the contact surfaces' displacements are found statically each step");
}

ContactSettings readContactSettings(const Teuchos::ParameterList& p, const std::string& file,
                                    const std::string& path) {
  ContactSettings s;
  s.path = path;
  const ParameterList& ct = p.sublist("Contact");
  s.method = ct.get<std::string>("Method");
  s.penaltyStiffness = ct.get<double>("Penalty Stiffness");
  s.augmentation = ct.get<double>("Augmentation Coefficient");
  s.gapTolerance = ct.get<double>("Gap Tolerance");
  s.maxActiveSetIterations = ct.get<int>("Maximum Active Set Iterations");
  s.redistributeMass = p.get<std::string>("Contact Mass") == "redistributed";
  if (s.enabled()) {
    const ParameterList& pairs = ct.sublist("Pairs");
    if (pairs.numParams() == 0)
      throwInput(file, path + "/Contact/Pairs", "", "contact method '" + s.method + "' needs a pair",
                 "add a sublist with 'Master Side Set' and 'Slave Side Set'");
    for (auto it = pairs.begin(); it != pairs.end(); ++it) {
      const ParameterList& pl = pairs.sublist(pairs.name(it));
      s.pairs.push_back({pairs.name(it), pl.get<std::string>("Master Side Set"),
                         pl.get<std::string>("Slave Side Set"), pl.get<double>("Search Distance")});
    }
  }
  if (s.redistributeMass && !s.enabled())
    throwInput(file, path + "/Contact Mass", "redistributed", "there are no contact surfaces",
               "set 'Contact/Method' and 'Contact/Pairs', or use 'standard'");
  return s;
}

namespace {

std::unique_ptr<ContactMethod> makeContactMethod(const ContactSettings& s) {
  if (s.method == "Lagrange") return makeLagrangeContact(s.gapTolerance);
  if (s.method == "Penalty") return makePenaltyContact(s.penaltyStiffness);
  return makeAugmentedLagrangianContact(s.augmentation, s.gapTolerance);
}

void requireSideSet(const Mesh& mesh, const std::string& name, const std::string& file,
                    const std::string& parameter) {
  if (mesh.findSideSet(name)) return;
  const auto names = mesh.sideSetNames();
  throwInput(file, parameter, name, "no side set of that name in the mesh",
             didYouMean(name, names) + "side sets: " + joinNames(names));
}

}  // namespace

std::unique_ptr<ContactManager> makeContactManager(const ContactSettings& s, const Mesh& mesh,
                                                   const DofMap& dofs, RCP<const Map> map,
                                                   const std::string& file) {
  if (!s.enabled()) return nullptr;
  for (const auto& pair : s.pairs) {
    const std::string pp = s.path + "/Contact/Pairs/" + pair.name;
    requireSideSet(mesh, pair.masterSideSet, file, pp + "/Master Side Set");
    requireSideSet(mesh, pair.slaveSideSet, file, pp + "/Slave Side Set");
  }
  try {
    return std::make_unique<ContactManager>(mesh, dofs, map, s.pairs, makeContactMethod(s));
  } catch (const std::invalid_argument& e) {
    throwInput(file, s.path + "/Contact/Pairs", "", e.what(),
               "check the side set names and 'Search Distance'");
  }
}

}  // namespace choc
