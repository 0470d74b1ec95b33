#include "physics/ModalLinks.hpp"

#include <cmath>
#include <sstream>

#include <Tpetra_MultiVector.hpp>

#include "fem/Components.hpp"
#include "fem/FieldGather.hpp"
#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Vector3.hpp"
#include "core/Format.hpp"

namespace choc {

void declareShockLinks(Teuchos::ParameterList& p) {
  ParameterList& l = declareNamedSublists(
      p, "Shock Links", "nonlinear two-node shock links (or node-to-fixed-obstacle), by name");
  declareRequiredString(l, "Node 1",
                        "node set of the first node; a set of k nodes makes k links '<name>.1' .. "
                        "'<name>.k', one per node, each with these parameters");
  declareString(l, "Node 2", "",
                "node set of the second node (with k nodes: each node of 'Node 1' is linked to "
                "the nearest of these, one to one); empty: a fixed obstacle at node 1's initial "
                "position");
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
}

namespace {

ModalLink readLink(const ParameterList& lp, const std::string& name, int node1, int node2,
                   const Model& model, const std::string& lpath) {
  const std::string& file = model.inputFile();
  const std::string n2 = lp.get<std::string>("Node 2");
  ModalLink l;
  l.name = name;
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
  const auto& X = model.mesh().coords;
  l.x1 = X[l.node1];
  l.x2 = l.node2 >= 0 ? X[l.node2] : X[l.node1];
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

std::vector<ModalLink> readShockLinks(const Teuchos::ParameterList& p, const Model& model,
                                      const std::string& path) {
  std::vector<ModalLink> out;
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


std::vector<std::string> shockLinkColumns(const std::vector<ModalLink>& links) {
  std::vector<std::string> c;
  for (const auto& l : links)
    for (const char* q : {":force", ":gap", ":status"}) c.push_back(l.name + q);
  return c;
}

ModalLinks::ModalLinks(std::vector<ModalLink> links, const Model& model, const ModalBasis& basis)
    : links_(std::move(links)) {
  modes_ = static_cast<int>(basis.eigenvalues.size());
  for (ModalLink& l : links_) {
    std::vector<long long> dofs;
    for (int c : {DX, DY, DZ}) dofs.push_back(model.dof(l.node1, c));
    for (int c : {DX, DY, DZ}) dofs.push_back(l.node2 >= 0 ? model.dof(l.node2, c) : -1);
    const std::vector<double> rows = gatherRows(*basis.vectors, dofs);
    l.phi1.assign(rows.begin(), rows.begin() + 3 * modes_);
    l.phi2.assign(rows.begin() + 3 * modes_, rows.end());
  }
  lastGapRate_.assign(links_.size(), 0.0);
  for (const auto& l : links_) hasRigid_ = hasRigid_ || l.law.rigid;
  constraintForce_.assign(modes_, 0.0);
}

std::vector<double> ModalLinks::historyValues() const {
  std::vector<double> v;
  for (const auto& l : links_) {
    v.push_back(l.last.normalForce);
    v.push_back(l.last.gap);
    v.push_back(l.last.closed ? 1.0 : 0.0);
  }
  return v;
}

std::vector<std::string> ModalLinks::globalNames() const {
  std::vector<std::string> g;
  for (const auto& l : links_)
    for (const char* q : {"_FORCE", "_GAP", "_STATUS"}) g.push_back(l.name + q);
  return g;
}

std::string ModalLinks::progressNote() const {
  std::string s;
  for (const auto& l : links_)
    s += (s.empty() ? "" : ", ") + l.name + (l.last.closed ? " closed, F = " : " open, F = ") +
         shortNumber(l.last.normalForce);
  return s.empty() ? "no links" : s;
}

Vec3 ModalLinks::relative(const ModalLink& l, const std::vector<double>& x, bool position) const {
  Vec3 d{0, 0, 0};
  for (int c = 0; c < 3; ++c) {
    double s = 0.0;
    const double* p1 = &l.phi1[c * modes_];
    const double* p2 = &l.phi2[c * modes_];
    for (int k = 0; k < modes_; ++k) s += (p2[k] - p1[k]) * x[k];
    d[c] = s + (position ? l.x2[c] - l.x1[c] : 0.0);
  }
  return d;
}

void ModalLinks::evaluate(double, const std::vector<double>& q, const std::vector<double>& v,
                          double dt, std::vector<double>& f) {
  std::fill(f.begin(), f.end(), 0.0);
  gapRate_.assign(links_.size(), 0.0);
  slipSpeed_.assign(links_.size(), 0.0);
  for (size_t i = 0; i < links_.size(); ++i) {
    ModalLink& l = links_[i];
    const Vec3 d = relative(l, q, true), w = relative(l, v, false);
    {  // kinematics along the shape's normal, open or closed (impact statistics)
      const ShockGeometry g = shockGeometry(l.law, d);
      gapRate_[i] = dot(w, g.normal);
      const Vec3 wt{w[0] - gapRate_[i] * g.normal[0], w[1] - gapRate_[i] * g.normal[1],
                    w[2] - gapRate_[i] * g.normal[2]};
      slipSpeed_[i] = std::sqrt(dot(wt, wt));
    }
    if (l.law.rigid) continue;  // enforced in project(); l.last was set there
    const double prevPower = l.last.closed ? l.law.normalDamping * lastGapRate_[i] * lastGapRate_[i] : 0.0;
    l.last = evaluateShock(l.law, d, w, dt, l.state, true);
    // f_q = Phi2^T F - Phi1^T F
    for (int c = 0; c < 3; ++c) {
      const double F = l.last.forceOnNode2[c];
      if (F == 0.0) continue;
      const double* p1 = &l.phi1[c * modes_];
      const double* p2 = &l.phi2[c * modes_];
      for (int k = 0; k < modes_; ++k) f[k] += (p2[k] - p1[k]) * F;
    }
    // Gap rate along the force direction, for the dissipation estimate and nearContact().
    const double fn = std::sqrt(dot(l.last.forceOnNode2, l.last.forceOnNode2));
    double rate = 0.0;
    if (fn > 0) rate = dot(w, l.last.forceOnNode2) / fn;
    const double power = l.last.closed && l.last.normalForce > 0 ? l.law.normalDamping * rate * rate : 0.0;
    linkDissipated_ += 0.5 * dt * (prevPower + power);
    lastGapRate_[i] = rate;
  }
}

bool ModalLinks::nearContact(double dt) const {
  for (size_t i = 0; i < links_.size(); ++i) {
    const ModalLink& l = links_[i];
    if (l.last.closed) return true;
    // Could close within two steps at a closing speed of at least the last gap rate.
    if (l.last.gap <= 2.0 * dt * std::abs(lastGapRate_[i]) + 1e-15) return true;
  }
  return false;
}

void ModalLinks::generalizedDirection(const ModalLink& l, const Vec3& m,
                                      std::vector<double>& b) const {
  b.assign(modes_, 0.0);
  for (int c = 0; c < 3; ++c) {
    if (m[c] == 0.0) continue;
    const double* p1 = &l.phi1[c * modes_];
    const double* p2 = &l.phi2[c * modes_];
    for (int k = 0; k < modes_; ++k) b[k] += (p2[k] - p1[k]) * m[c];
  }
}

void ModalLinks::project(double h, std::vector<double>& q, std::vector<double>& v) {
  std::vector<double> b;
  std::fill(constraintForce_.begin(), constraintForce_.end(), 0.0);
  for (auto& l : links_) {
    if (!l.law.rigid) continue;
    // lambda_n >= 0 such that gap(q_{n+1}) >= 0, lambda gap = 0. The gap is linear in q along
    // a fixed normal (planes); curved shapes converge in a few Newton-like passes.
    double lambda = 0.0;
    if (l.law.shape == ObstacleShape::BiCercInt && l.law.dist2 - l.law.dist1 <= 0.0) {
      // No free play: the inner circle cannot move in the plane orthogonal to the axis, a
      // bilateral tie d.e2 = d.e3 = 0 (the radial normal is undefined at r = 0).
      Vec3 force{0, 0, 0};
      for (int pass = 0; pass < 2; ++pass)
        for (const Vec3* e : {&l.law.frame.e2, &l.law.frame.e3}) {
          generalizedDirection(l, *e, b);
          double w = 0.0;
          for (double x : b) w += x * x;
          if (!(w > 0)) continue;
          const double dl = -dot(relative(l, q, true), *e) / (h * h * w);
          for (int k = 0; k < modes_; ++k) {
            q[k] += h * h * dl * b[k];
            v[k] += h * dl * b[k];
            constraintForce_[k] += dl * b[k];
          }
          for (int c = 0; c < 3; ++c) force[c] += dl * (*e)[c];
        }
      const Vec3 d = relative(l, q, true);
      l.last = ShockResponse{};
      l.last.gap = -std::sqrt(std::pow(dot(d, l.law.frame.e2), 2) + std::pow(dot(d, l.law.frame.e3), 2));
      l.last.forceOnNode2 = force;
      l.last.normalForce = std::sqrt(dot(force, force));
      l.last.closed = true;
      continue;
    }
    ShockGeometry g = shockGeometry(l.law, relative(l, q, true));
    for (int pass = 0; pass < 4 && g.gap < 0.0; ++pass) {
      generalizedDirection(l, g.normal, b);
      double w = 0.0;
      for (double x : b) w += x * x;
      if (!(w > 0)) break;  // the basis cannot move the link: nothing to enforce
      const double dl = -g.gap / (h * h * w);
      for (int k = 0; k < modes_; ++k) {
        q[k] += h * h * dl * b[k];
        v[k] += h * dl * b[k];
        constraintForce_[k] += dl * b[k];
      }
      lambda += dl;
      g = shockGeometry(l.law, relative(l, q, true));
      if (std::abs(g.gap) <= 1e-14 * (l.law.dist1 + l.law.dist2 + 1e-12)) break;
    }
    l.last = ShockResponse{};
    l.last.gap = g.gap;
    l.last.normalForce = lambda;
    l.last.closed = lambda > 0.0;
    for (int c = 0; c < 3; ++c) l.last.forceOnNode2[c] = lambda * g.normal[c];
  }
}

double ModalLinks::linkOmega2Bound() const {
  double s = 0.0;
  for (const auto& l : links_) {
    if (l.law.rigid) continue;  // a constraint adds no frequency to the explicit scheme
    double flex = 0.0;
    for (int k = 0; k < modes_; ++k) {
      double dk2 = 0.0;
      for (int c = 0; c < 3; ++c) {
        const double d = l.phi2[c * modes_ + k] - l.phi1[c * modes_ + k];
        dk2 += d * d;
      }
      flex += dk2;
    }
    s += l.law.normalStiffness * flex;
  }
  return s;
}

double ModalLinks::linkDampingRatioBound() const {
  double xi = 0.0;
  for (const auto& l : links_) {
    if (l.law.rigid) continue;  // no dashpot in the rigid law
    double flex = 0.0;
    for (int k = 0; k < modes_; ++k)
      for (int c = 0; c < 3; ++c) {
        const double d = l.phi2[c * modes_ + k] - l.phi1[c * modes_ + k];
        flex += d * d;
      }
    // Effective mass m = 1/flex; xi = C / (2 sqrt(K m)).
    if (flex > 0 && l.law.normalStiffness > 0)
      xi = std::max(xi, l.law.normalDamping / (2.0 * std::sqrt(l.law.normalStiffness / flex)));
  }
  return xi;
}

double ModalLinks::springEnergy() const {
  double e = 0.0;
  for (const auto& l : links_) e += l.last.springEnergy;
  return e;
}

void ModalLinks::archive(StateArchive& a) const {
  std::vector<ShockLawState> states;
  std::vector<ShockResponse> last;
  for (const auto& l : links_) {
    states.push_back(l.state);
    last.push_back(l.last);
  }
  a.putVector("links/states", states);
  a.putVector("links/responses", last);
  a.putVector("links/gapRates", lastGapRate_);
  a.putVector("links/constraintForce", constraintForce_);
  a.putDouble("links/dissipated", linkDissipated_);
}

void ModalLinks::unarchive(const StateArchive& a) {
  const auto states = a.getVector<ShockLawState>("links/states", links_.size());
  const auto last = a.getVector<ShockResponse>("links/responses", links_.size());
  for (size_t i = 0; i < links_.size(); ++i) {
    links_[i].state = states[i];
    links_[i].last = last[i];
  }
  lastGapRate_ = a.getVector<double>("links/gapRates", links_.size());
  constraintForce_ = a.getVector<double>("links/constraintForce", constraintForce_.size());
  linkDissipated_ = a.getDouble("links/dissipated");
}

std::vector<std::string> ModalLinks::impactNames() const {
  std::vector<std::string> n;
  for (const auto& l : links_) n.push_back(l.name);
  return n;
}

std::vector<ImpactSample> ModalLinks::impactSamples() const {
  std::vector<ImpactSample> out(links_.size());
  for (size_t i = 0; i < links_.size(); ++i) {
    const ShockResponse& r = links_[i].last;
    out[i].force = r.normalForce;
    out[i].gap = r.gap;
    out[i].gapRate = i < gapRate_.size() ? gapRate_[i] : 0.0;
    out[i].tangentialForce = r.tangentialForce;
    out[i].slipSpeed = i < slipSpeed_.size() ? slipSpeed_[i] : 0.0;
  }
  return out;
}

}  // namespace choc
