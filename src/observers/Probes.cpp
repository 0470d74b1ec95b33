#include "observers/Probes.hpp"

#include <set>
#include <sstream>

#include "fem/Components.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"

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
  std::set<std::string> columns, noted;
  while (in >> token) {
    const auto colon = token.find(':');
    if (colon == std::string::npos || colon == 0 || colon + 1 == token.size() ||
        token.find('"') != std::string::npos)
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
    if (!columns.insert(token).second)
      throwInput(model.inputFile(), parameter, token, "is given twice", "record each quantity once");
    p.node = ns.nodes.front();
    if (ns.nodes.size() > 1 && noted.insert(set).second) {
      const Point3& x = model.mesh().coords[p.node];
      log() << format("  history: node set '%s' has %zu nodes; its columns record its first node, %d "
                      "at (%.6g, %.6g, %.6g)\n",
                      set.c_str(), ns.nodes.size(), p.node + 1, x[0], x[1], x[2]);
    }
    p.component = comp;
    p.dof = model.dof(p.node, comp);
    probes.push_back(p);
  }
  return probes;
}

}  // namespace choc
