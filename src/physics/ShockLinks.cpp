#include "physics/ShockLinks.hpp"

#include <cmath>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Vector3.hpp"

namespace choc {

void declareShockLinks(Teuchos::ParameterList& p) {
  ParameterList& l = declareNamedSublists(
      p, "Shock Links",
      "nonlinear two-node shock links (or node-to-fixed-obstacle), by name (the name starts the "
      "link's result columns: 1 to 32 letters, digits, '_', '-', '.')",
      NamedAs::OutputName);
  declareRequiredString(l, "Node 1",
                        "node set of the first node; a set of k nodes makes k links '<name>.1' .. "
                        "'<name>.k', one per node, each with these parameters");
  declareString(l, "Node 2", "",
                "node set of the second node (with k nodes: each node of 'Node 1' is linked to "
                "the nearest of these, one to one); empty: a fixed obstacle, at 'Obstacle Origin'");
  declareString(l, "Obstacle Origin", "",
                "position 'x y z' of a fixed obstacle's origin (ORIG_OBST; only when 'Node 2' is "
                "empty): a plane passes through it, a circle is centred on its axis; empty: node "
                "1's initial position (each node of a set its own)");
  declareChoice(l, "Obstacle", "BI_PLAN_Z", obstacleShapeNames(),
                "shape: two planes normal to the local y or z axis, two circles, an inner "
                "circle moving in an outer circle, or one plane (a unilateral stop, PLAN_Y / "
                "PLAN_Z) whose outward normal is the local y / z axis");
  declareString(l, "Axis", "0 0 1", "obstacle axis n (NORM_OBST) 'x y z'");
  declareDouble(l, "Twist", 0.0, "rotation of the local y, z axes about n [degrees] (ANGL_VRIL)");
  declareDouble(l, "DIST_1", 0.0, "offset of node 1 (inner radius for BI_CERC_INT) [m]",
                Range::nonNegative());
  declareDouble(l, "DIST_2", 0.0, "offset of node 2 (outer radius for BI_CERC_INT) [m]",
                Range::nonNegative());
  declareChoice(l, "Normal Law", "penalty", {"penalty", "rigid"},
                "penalty: force max(0, -Kn delta - Cn delta'); rigid: no penetration, enforced "
                "by a forward-increment Lagrange multiplier (the stiffness and damping are then "
                "not used)");
  declareDouble(l, "Normal Stiffness", 0.0, "Kn [N/m] (required for the penalty law)",
                Range::nonNegative());
  declareDouble(l, "Normal Damping", 0.0, "Cn [N s/m]", Range::nonNegative());
  declareDouble(l, "Tangential Stiffness", 0.0, "Kt [N/m]", Range::nonNegative());
  declareDouble(l, "Tangential Damping", 0.0, "Ct [N s/m]", Range::nonNegative());
  declareDouble(l, "Friction Coefficient", 0.0, "Coulomb coefficient mu", Range::nonNegative());
  declareChoice(l, "Friction Law", "elastic-plastic", {"elastic-plastic", "velocity reversal"},
                "elastic-plastic: a tangential spring Kt returned onto the Coulomb cone; velocity "
                "reversal: code_aster's DIS_CHOC (slip along the velocity, stick when it reverses; "
                "see src/contact/ShockLaw.hpp)");
}

namespace {

ShockLink readLink(const ParameterList& lp, const std::string& name, int node1, int node2,
                   const Model& model, const std::string& lpath) {
  const std::string& file = model.inputFile();
  const std::string n2 = lp.get<std::string>("Node 2");
  ShockLink l;
  l.name = name;
  l.path = lpath;
  l.node1 = node1;
  l.node2 = node2;
  if (l.node2 == l.node1)
    throwInput(file, lpath + "/Node 2", n2, "is the same node as Node 1",
               "link two different nodes, or leave Node 2 empty for a fixed obstacle");
  l.law.shape = parseObstacleShape(lp.get<std::string>("Obstacle"));
  const Vec3 axis = parseVector3(lp.get<std::string>("Axis"), file, lpath + "/Axis");
  if (!(dot(axis, axis) > 0)) throwInput(file, lpath + "/Axis", lp.get<std::string>("Axis"), "must not be zero");
  l.law.frame = obstacleFrame(axis, lp.get<double>("Twist") * M_PI / 180.0);
  l.law.dist1 = lp.get<double>("DIST_1");
  l.law.dist2 = lp.get<double>("DIST_2");
  if (l.law.shape == ObstacleShape::BiCercInt && l.law.dist2 < l.law.dist1)
    throwInput(file, lpath + "/DIST_2", std::to_string(l.law.dist2),
               "is smaller than DIST_1 = " + std::to_string(l.law.dist1),
               "BI_CERC_INT needs the outer radius DIST_2 >= the inner radius DIST_1");
  l.law.rigid = lp.get<std::string>("Normal Law") == "rigid";
  l.law.normalStiffness = lp.get<double>("Normal Stiffness");
  if (!l.law.rigid && !(l.law.normalStiffness > 0))
    throwInput(file, lpath + "/Normal Stiffness", std::to_string(l.law.normalStiffness),
               "must be positive for the penalty law",
               "give the link stiffness [N/m], or set 'Normal Law' to 'rigid'");
  l.law.normalDamping = lp.get<double>("Normal Damping");
  l.law.tangentialStiffness = lp.get<double>("Tangential Stiffness");
  l.law.tangentialDamping = lp.get<double>("Tangential Damping");
  l.law.friction = lp.get<double>("Friction Coefficient");
  l.law.frictionLaw = lp.get<std::string>("Friction Law") == "velocity reversal" ? FrictionLaw::VelocityReversal
                                                                                 : FrictionLaw::ElasticPlastic;
  if (l.law.rigid && l.law.tangential())
    throwInput(file, lpath + "/Normal Law", "rigid",
               "carries no tangential force (the link has a tangential stiffness, damping or friction)",
               "use the penalty law for a link with friction");
  const auto& X = model.mesh().coords;
  l.x1 = X[l.node1];
  l.x2 = l.node2 >= 0 ? X[l.node2] : X[l.node1];
  const std::string origin = lp.get<std::string>("Obstacle Origin");
  if (!origin.empty()) {
    if (l.node2 >= 0)
      throwInput(file, lpath + "/Obstacle Origin", origin, "places a fixed obstacle, but 'Node 2' = '" + n2 + "' is given",
                 "leave 'Node 2' empty for a fixed obstacle at this origin, or leave 'Obstacle Origin' empty");
    l.x2 = parseVector3(origin, file, lpath + "/Obstacle Origin");
  }
  return l;
}


// The node pairs of one 'Shock Links' entry: every node of 'Node 1' with the nearest node of
// 'Node 2' (one to one), or with a fixed obstacle (-1).
std::vector<std::pair<int, int>> linkNodePairs(const ParameterList& lp, const Model& model,
                                               const std::string& lpath) {
  const std::vector<int>& set1 = model.nodeSet(lp.get<std::string>("Node 1"), lpath + "/Node 1").nodes;
  const std::string n2 = lp.get<std::string>("Node 2");
  std::vector<std::pair<int, int>> pairs;
  if (n2.empty()) {
    for (int n : set1) pairs.emplace_back(n, -1);
    return pairs;
  }
  const std::vector<int>& set2 = model.nodeSet(n2, lpath + "/Node 2").nodes;
  if (set2.size() != set1.size())
    throwInput(model.inputFile(), lpath + "/Node 2", n2,
               "has " + std::to_string(set2.size()) + " nodes, 'Node 1' has " + std::to_string(set1.size()),
               "give two node sets of as many nodes, facing each other");
  const auto& X = model.mesh().coords;
  std::vector<char> used(set2.size(), 0);
  for (int a : set1) {
    int best = -1;
    double bestD = INFINITY;
    for (size_t j = 0; j < set2.size(); ++j) {
      double d = 0;
      for (int c = 0; c < 3; ++c) d += (X[a][c] - X[set2[j]][c]) * (X[a][c] - X[set2[j]][c]);
      if (d < bestD) bestD = d, best = int(j);
    }
    if (used[best])
      throwInput(model.inputFile(), lpath + "/Node 2", n2,
                 "node " + std::to_string(set2[best] + 1) + " is the nearest of two nodes of 'Node 1'",
                 "give node sets whose nodes face each other one to one");
    used[best] = 1;
    pairs.emplace_back(a, set2[best]);
  }
  return pairs;
}

}  // namespace

std::vector<ShockLink> readShockLinks(const Teuchos::ParameterList& p, const Model& model,
                                      const std::string& path) {
  std::vector<ShockLink> out;
  const ParameterList& links = p.sublist("Shock Links");
  for (auto it = links.begin(); it != links.end(); ++it) {
    const std::string name = links.name(it), lpath = path + "/Shock Links/" + name;
    const ParameterList& lp = links.sublist(name);
    const auto pairs = linkNodePairs(lp, model, lpath);
    for (size_t i = 0; i < pairs.size(); ++i)
      out.push_back(readLink(lp, pairs.size() == 1 ? name : name + "." + std::to_string(i + 1),
                             pairs[i].first, pairs[i].second, model, lpath));
  }
  return out;
}


std::vector<std::string> shockLinkColumns(const std::vector<ShockLink>& links) {
  std::vector<std::string> c;
  for (const auto& l : links) {
    for (const char* q : {":force", ":gap", ":status"}) c.push_back(l.name + q);
    if (l.law.tangential())
      for (const char* q : {":tangential_force", ":slip_velocity", ":friction_work"}) c.push_back(l.name + q);
  }
  return c;
}

ShockLinkSet::ShockLinkSet(std::vector<ShockLink> links) : links_(std::move(links)) {
  lastGapRate_.assign(links_.size(), 0.0);
  tangentialWork_.assign(links_.size(), 0.0);
  lastTangentialPower_.assign(links_.size(), 0.0);
  gapRate_.assign(links_.size(), 0.0);
  slipSpeed_.assign(links_.size(), 0.0);
}

std::vector<double> ShockLinkSet::historyValues() const {
  std::vector<double> v;
  for (size_t i = 0; i < links_.size(); ++i) {
    const ShockLink& l = links_[i];
    v.push_back(l.last.normalForce);
    v.push_back(l.last.gap);
    v.push_back(l.last.closed ? (l.last.sliding ? 2.0 : 1.0) : 0.0);
    if (l.law.tangential()) {
      v.push_back(l.last.tangentialForce);
      v.push_back(l.last.slipSpeed);
      v.push_back(frictionWork(i));
    }
  }
  return v;
}

double ShockLinkSet::frictionWork(size_t i) const {
  return tangentialWork_[i] - links_[i].last.tangentialEnergy;
}

double ShockLinkSet::dissipatedEnergy() const {
  double e = dissipated_;
  for (size_t i = 0; i < links_.size(); ++i) e += frictionWork(i);
  return e;
}

void ShockLinkSet::accumulateTangentialPower(size_t i, const Vec3& w, double dt) {
  const double power = -dot(links_[i].last.tangentialForceVector, w);
  tangentialWork_[i] += 0.5 * dt * (lastTangentialPower_[i] + power);
  lastTangentialPower_[i] = power;
}

std::vector<std::string> ShockLinkSet::globalNames() const {
  std::vector<std::string> g;
  for (const auto& l : links_) {
    for (const char* q : {"_FORCE", "_GAP", "_STATUS"}) g.push_back(l.name + q);
    if (l.law.tangential())
      for (const char* q : {"_TANGENTIAL_FORCE", "_SLIP_VELOCITY", "_FRICTION_WORK"}) g.push_back(l.name + q);
  }
  return g;
}

std::string ShockLinkSet::progressNote() const {
  std::string s;
  for (const auto& l : links_)
    s += (s.empty() ? "" : ", ") + l.name + (l.last.closed ? " closed, F = " : " open, F = ") +
         shortNumber(l.last.normalForce);
  return s.empty() ? "no links" : s;
}

double ShockLinkSet::springEnergy() const {
  double e = 0.0;
  for (const auto& l : links_) e += l.last.springEnergy;
  return e;
}

void ShockLinkSet::recordKinematics(size_t i, const Vec3& d, const Vec3& w) {
  const ShockGeometry g = shockGeometry(links_[i].law, d);
  gapRate_[i] = dot(w, g.normal);
  const Vec3 wt{w[0] - gapRate_[i] * g.normal[0], w[1] - gapRate_[i] * g.normal[1],
                w[2] - gapRate_[i] * g.normal[2]};
  slipSpeed_[i] = std::sqrt(dot(wt, wt));
}

void ShockLinkSet::accumulateDissipation(size_t i, bool wasClosed, const Vec3& w, double dt) {
  const ShockLink& l = links_[i];
  const double prevPower = wasClosed ? l.law.normalDamping * lastGapRate_[i] * lastGapRate_[i] : 0.0;
  // Gap rate along the force direction.
  const double fn = std::sqrt(dot(l.last.forceOnNode2, l.last.forceOnNode2));
  const double rate = fn > 0 ? dot(w, l.last.forceOnNode2) / fn : 0.0;
  const double power = l.last.closed && l.last.normalForce > 0 ? l.law.normalDamping * rate * rate : 0.0;
  dissipated_ += 0.5 * dt * (prevPower + power);
  lastGapRate_[i] = rate;
}

void ShockLinkSet::archiveLinks(StateArchive& a) const {
  std::vector<ShockLawState> states;
  std::vector<ShockResponse> last;
  for (const auto& l : links_) {
    states.push_back(l.state);
    last.push_back(l.last);
  }
  a.putVector("links/states", states);
  a.putVector("links/responses", last);
  a.putVector("links/gapRates", lastGapRate_);
  a.putDouble("links/dissipated", dissipated_);
  a.putVector("links/tangentialWork", tangentialWork_);
  a.putVector("links/tangentialPower", lastTangentialPower_);
}

void ShockLinkSet::restoreLinks(const StateArchive& a) {
  const auto states = a.getVector<ShockLawState>("links/states", links_.size());
  const auto last = a.getVector<ShockResponse>("links/responses", links_.size());
  for (size_t i = 0; i < links_.size(); ++i) {
    links_[i].state = states[i];
    links_[i].last = last[i];
  }
  lastGapRate_ = a.getVector<double>("links/gapRates", links_.size());
  dissipated_ = a.getDouble("links/dissipated");
  tangentialWork_ = a.getVector<double>("links/tangentialWork", links_.size());
  lastTangentialPower_ = a.getVector<double>("links/tangentialPower", links_.size());
}

std::vector<std::string> ShockLinkSet::impactNames() const {
  std::vector<std::string> n;
  for (const auto& l : links_) n.push_back(l.name);
  return n;
}

std::vector<ImpactSample> ShockLinkSet::impactSamples() const {
  std::vector<ImpactSample> out(links_.size());
  for (size_t i = 0; i < links_.size(); ++i) {
    const ShockResponse& r = links_[i].last;
    out[i].force = r.normalForce;
    out[i].gap = r.gap;
    out[i].gapRate = gapRate_[i];
    out[i].tangentialForce = r.tangentialForce;
    out[i].slipSpeed = slipSpeed_[i];
  }
  return out;
}

}  // namespace choc
