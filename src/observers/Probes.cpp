#include "observers/Probes.hpp"

#include <sstream>

#include "fem/Components.hpp"
#include "core/Errors.hpp"

namespace choc {

std::vector<Probe> parseProbes(const std::string& text, const Model& model,
                               const std::string& parameter) {
  std::vector<Probe> probes;
  std::string t = text;
  for (char& c : t)
    if (c == ',') c = ' ';
  std::istringstream in(t);
  std::string token;
  const std::string valid = "<node set>:<DX|DY|DZ|DRX|DRY|DRZ|VX|VY|VZ|AX|AY|AZ>, e.g. 'A:DX'";
  while (in >> token) {
    const auto colon = token.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == token.size())
      throwInput(model.inputFile(), parameter, token, "malformed history quantity", "write " + valid);
    const std::string set = token.substr(0, colon), q = token.substr(colon + 1);
    Probe p;
    p.column = token;
    int comp = componentFromName(q);
    if (comp >= 0) {
      p.field = ProbeField::Displacement;
    } else if (q.size() == 2 && (q[0] == 'V' || q[0] == 'A') &&
               (comp = componentFromName(std::string("D") + q[1])) >= 0) {
      p.field = q[0] == 'V' ? ProbeField::Velocity : ProbeField::Acceleration;
    } else {
      throwInput(model.inputFile(), parameter, token, "unknown quantity '" + q + "'", "write " + valid);
    }
    const NodeSet& ns = model.nodeSet(set, parameter);
    if (ns.nodes.empty()) throwInput(model.inputFile(), parameter, token, "node set '" + set + "' is empty");
    p.node = ns.nodes.front();
    p.component = comp;
    p.dof = model.dof(p.node, comp);
    probes.push_back(p);
  }
  return probes;
}

}  // namespace choc
