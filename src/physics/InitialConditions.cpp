#include "physics/InitialConditions.hpp"

#include <Tpetra_Vector.hpp>

#include "fem/Components.hpp"
#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

void declareInitialConditions(Teuchos::ParameterList& p) {
  ParameterList& ic = declareNamedSublists(
      p, "Initial Conditions", "initial fields, by name (unset components start at zero)");
  declareRequiredString(ic, "Node Set", "node set receiving the value");
  declareChoice(ic, "Field", "Velocity", {"Velocity", "Displacement"}, "which initial field");
  declareRequiredString(ic, "Components", "components set, e.g. 'DX' (velocity too: 'DX' = VX)");
  declareRequiredDouble(ic, "Value", "value [m/s or m]");
}

InitialFields buildInitialFields(const Teuchos::ParameterList& p, const Model& model,
                                 const std::string& analysisPath) {
  InitialFields f;
  f.displacement = rcp(new Vector(model.map()));
  f.velocity = rcp(new Vector(model.map()));
  const ParameterList& ic = p.sublist("Initial Conditions");
  for (auto it = ic.begin(); it != ic.end(); ++it) {
    const std::string path = analysisPath + "/Initial Conditions/" + ic.name(it);
    const ParameterList& c = ic.sublist(ic.name(it));
    const NodeSet& ns = model.nodeSet(c.get<std::string>("Node Set"), path + "/Node Set");
    std::vector<int> comps;
    try {
      comps = parseComponents(c.get<std::string>("Components"));
    } catch (const std::invalid_argument& e) {
      throwInput(model.inputFile(), path + "/Components", c.get<std::string>("Components"), e.what());
    }
    const double value = c.get<double>("Value");
    Vector& target = c.get<std::string>("Field") == "Velocity" ? *f.velocity : *f.displacement;
    for (int n : ns.nodes) {
      if (!model.dofs().ownsNode(n)) continue;
      for (int comp : comps) {
        const long long d = model.dof(n, comp);
        if (d >= 0) target.replaceGlobalValue(GO(d), value);
      }
    }
  }
  return f;
}

}  // namespace choc
