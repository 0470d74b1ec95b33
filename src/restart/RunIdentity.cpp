#include "restart/RunIdentity.hpp"

#include <cstdio>
#include <cstdlib>
#include <map>
#include <sstream>
#include <vector>

namespace choc {

namespace {

bool tolerant(const std::string& path, const std::string& analysis) {
  const std::string mine = "Analyses/" + analysis + "/";
  if (path == mine + "End Time") return true;
  if (path.rfind("Analyses/", 0) == 0) {
    if (path.find("/Checkpoint/") != std::string::npos) return true;
    const std::string key = "/Progress Interval";
    if (path.size() > key.size() && path.compare(path.size() - key.size(), key.size(), key) == 0) return true;
  }
  return false;
}

// Doubles in their shortest form that reads back to the same value (1e-06, not
// 9.9999999999999995e-07); everything else as Teuchos prints it.
std::string valueText(const Teuchos::ParameterEntry& e) {
  if (e.isType<double>()) {
    const double x = Teuchos::getValue<double>(e);
    char b[40];
    for (int p = 1; p <= 17; ++p) {
      std::snprintf(b, sizeof b, "%.*g", p, x);
      if (std::strtod(b, nullptr) == x) break;
    }
    return b;
  }
  std::ostringstream v;
  e.leftshift(v, false);
  return v.str();
}

void flatten(const Teuchos::ParameterList& list, const std::string& prefix, const std::string& analysis,
             std::ostringstream& out) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string name = list.name(it);
    const std::string path = prefix.empty() ? name : prefix + "/" + name;
    const Teuchos::ParameterEntry& e = list.entry(it);
    if (e.isList()) {
      flatten(list.sublist(name), path, analysis, out);
      continue;
    }
    if (tolerant(path, analysis)) continue;
    out << path << " = " << valueText(e) << "\n";
  }
}

std::map<std::string, std::string> lines(const std::string& text) {
  std::map<std::string, std::string> m;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    if (eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 3);
  }
  return m;
}

}  // namespace

std::string canonicalInput(const Teuchos::ParameterList& input, const std::string& analysis) {
  std::ostringstream out;
  flatten(input, "", analysis, out);
  return out.str();
}

std::uint64_t meshHash(const Mesh& mesh) {
  std::uint64_t h = fnv1a(mesh.coords.data(), mesh.coords.size() * sizeof(Point3));
  for (const ElementBlock& b : mesh.blocks) {
    h = fnv1a(b.topology.data(), b.topology.size(), h);
    h = fnv1a(b.connectivity.data(), b.connectivity.size() * sizeof(int), h);
  }
  for (const NodeSet& s : mesh.nodeSets) {
    h = fnv1a(s.name.data(), s.name.size(), h);
    h = fnv1a(s.nodes.data(), s.nodes.size() * sizeof(int), h);
  }
  for (const SideSet& s : mesh.sideSets) {
    h = fnv1a(s.name.data(), s.name.size(), h);
    h = fnv1a(s.elements.data(), s.elements.size() * sizeof(int), h);
    h = fnv1a(s.sides.data(), s.sides.size() * sizeof(int), h);
  }
  return h;
}

void RunIdentity::save(StateArchive& a) const {
  a.putText("identity/analysis", analysis);
  a.putText("identity/input", input);
  a.putVector("identity/mesh", std::vector<std::uint64_t>{mesh});
  a.putInt("identity/ranks", ranks);
}

RunIdentity RunIdentity::load(const StateArchive& a) {
  RunIdentity id;
  id.analysis = a.text("identity/analysis");
  id.input = a.text("identity/input");
  id.mesh = a.getVector<std::uint64_t>("identity/mesh", 1)[0];
  id.ranks = static_cast<int>(a.getInt("identity/ranks"));
  return id;
}

std::string RunIdentity::mismatch(const RunIdentity& now) const {
  if (input != now.input) {
    const auto was = lines(input), is = lines(now.input);
    for (const auto& [k, v] : is) {
      const auto it = was.find(k);
      if (it == was.end()) return "parameter '" + k + "' = '" + v + "' is not in the checkpoint's input";
      if (it->second != v)
        return "parameter '" + k + "' is '" + v + "' in the input, '" + it->second + "' in the checkpoint";
    }
    for (const auto& [k, v] : was)
      if (!is.count(k)) return "parameter '" + k + "' = '" + v + "' of the checkpoint's input is not in the input";
    return "the input differs from the checkpoint's";
  }
  if (mesh != now.mesh)
    return "the mesh differs from the checkpoint's (hash " + hex64(now.mesh) + ", checkpoint " + hex64(mesh) + ")";
  return "";
}

}  // namespace choc
