#include "observers/Probes.hpp"

#include <set>
#include <sstream>

#include "fem/Components.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"

namespace choc {

namespace {

// PX..PZ, LX..LZ: the field and component (-1: not a momentum).
int momentumComponent(const std::string& q, ProbeField& field) {
  if (q.size() != 2 || (q[0] != 'P' && q[0] != 'L') || q[1] < 'X' || q[1] > 'Z') return -1;
  field = q[0] == 'P' ? ProbeField::Momentum : ProbeField::AngularMomentum;
  return q[1] - 'X';
}

// The set's nodes for a momentum probe, or an input error where the quantity has no meaning.
void momentumNodes(Probe& p, const NodeSet& ns, const Model& model, const std::string& parameter,
                   const std::string& token, bool allowed) {
  const std::string what = "a node set's momentum";
  if (!allowed)
    throwInput(model.inputFile(), parameter, token, what + " is recorded by the direct transient only",
               "record it in a 'Transient' analysis, or record velocities here");
  if (model.kinematics() == Kinematics::Axisymmetric)
    throwInput(model.inputFile(), parameter, token, what + " is not recorded in axisymmetry",
               "use a 3D or plane-strain model");
  const bool plane = model.kinematics() == Kinematics::PlaneStrain;
  const bool inPlane = p.field == ProbeField::Momentum ? p.component < 2 : p.component == 2;
  if (plane && !inPlane)
    throwInput(model.inputFile(), parameter, token, "not in the plane of a plane-strain model",
               "record PX, PY or LZ");
  for (int n : ns.nodes) {
    if (model.dof(n, 3) >= 0 || model.dof(n, 5) >= 0)
      throwInput(model.inputFile(), parameter, token,
                 "node set '" + ns.name + "' has rotation DOFs (beams), whose inertia is not counted",
                 "record the momentum of a set of solid nodes");
    p.X.push_back(model.mesh().coords[size_t(n)]);
    p.dofs.push_back({model.dof(n, 0), model.dof(n, 1), plane ? -1LL : model.dof(n, 2)});
  }
}

}  // namespace

std::vector<Probe> parseProbes(const std::string& text, const Model& model, const std::string& parameter,
                               bool momenta) {
  std::vector<Probe> probes;
  std::string t = text;
  for (char& c : t)
    if (c == ',') c = ' ';
  std::istringstream in(t);
  std::string token;
  const std::string valid =
      "<node set>:<DX|DY|DZ|DRX|DRY|DRZ|VX|VY|VZ|AX|AY|AZ|PX|PY|PZ|LX|LY|LZ>, e.g. 'A:DX'";
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
    } else if ((comp = momentumComponent(q, p.field)) >= 0) {
    } else {
      throwInput(model.inputFile(), parameter, token, "unknown quantity '" + q + "'", "write " + valid);
    }
    const NodeSet& ns = model.nodeSet(set, parameter);
    if (ns.nodes.empty()) throwInput(model.inputFile(), parameter, token, "node set '" + set + "' is empty");
    if (!columns.insert(token).second)
      throwInput(model.inputFile(), parameter, token, "is given twice", "record each quantity once");
    if (p.field == ProbeField::Momentum || p.field == ProbeField::AngularMomentum) {
      p.component = comp;
      momentumNodes(p, ns, model, parameter, token, momenta);
      probes.push_back(p);
      continue;
    }
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
