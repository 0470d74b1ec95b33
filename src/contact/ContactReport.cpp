#include "contact/ContactReport.hpp"

#include <algorithm>
#include <limits>

namespace choc {

void ContactReport::update(const Vector& u, const Vector& v, double t) {
  forces_ = contact_.forces(u);
  gaps_ = contact_.gaps(u);
  rates_ = contact_.gapRates(v);
  u_ = &u;  // the slips are gathered only when the nodal fields are written
  time_ = t;
}

std::vector<std::string> ContactReport::historyColumns() const {
  std::vector<std::string> c;
  for (int p = 0; p < contact_.numPairs(); ++p) {
    c.push_back(contact_.pair(p).name + ":force");
    c.push_back(contact_.pair(p).name + ":gap");
    c.push_back(contact_.pair(p).name + ":area");
    if (contact_.hasFriction()) {
      c.push_back(contact_.pair(p).name + ":tangential_force");
      c.push_back(contact_.pair(p).name + ":friction_work");
    }
  }
  return c;
}

std::vector<double> ContactReport::historyValues() const {
  std::vector<double> vals;
  for (int p = 0; p < contact_.numPairs(); ++p) {
    double force = 0.0, gap = std::numeric_limits<double>::infinity(), area = 0.0;
    for (int s = 0; s < contact_.numConstraints(); ++s)
      if (contact_.constraints()[s].geometry.pair == p) {
        force += forces_[s];
        gap = std::min(gap, gaps_[s]);
        if (contact_.status()[s]) area += contact_.constraints()[s].geometry.area;
      }
    vals.push_back(force);
    vals.push_back(gap);
    vals.push_back(area);
    if (contact_.hasFriction()) {
      Vec3 ft{0, 0, 0};
      for (int s = 0; s < contact_.numConstraints(); ++s)
        if (contact_.constraints()[s].geometry.pair == p)
          for (int d = 0; d < 3; ++d) ft[d] += contact_.friction()->forces()[s][d];
      vals.push_back(norm(ft));
      vals.push_back(contact_.friction()->dissipation(p));
    }
  }
  return vals;
}

std::vector<std::string> ContactReport::nodalFieldNames() const {
  std::vector<std::string> names = {"CONTACT_FORCE", "CONTACT_PRESSURE", "CONTACT_GAP",
                                    "CONTACT_STATUS", "CONTACT_SLIP"};
  if (contact_.hasFriction()) names.push_back("CONTACT_TANGENTIAL_TRACTION");
  return names;
}

std::vector<std::vector<double>> ContactReport::nodalFields() const {
  std::vector<double> force(numNodes_, 0.0), pressure(numNodes_, 0.0), gap(numNodes_, 0.0),
      status(numNodes_, 0.0), slip(numNodes_, 0.0);
  const std::vector<double> slips = contact_.slips(*u_, time_);
  for (int s = 0; s < contact_.numConstraints(); ++s) {
    const auto& geo = contact_.constraints()[s].geometry;
    force[geo.slaveNode] = forces_[s];
    pressure[geo.slaveNode] = geo.area > 0 ? forces_[s] / geo.area : 0.0;
    gap[geo.slaveNode] = gaps_[s];
    status[geo.slaveNode] = contact_.status()[s] ? 1.0 : 0.0;
    slip[geo.slaveNode] = slips[s];
  }
  if (!contact_.hasFriction()) return {force, pressure, gap, status, slip};
  std::vector<double> traction(numNodes_, 0.0);
  for (int s = 0; s < contact_.numConstraints(); ++s) {
    const auto& geo = contact_.constraints()[s].geometry;
    if (contact_.friction()->status()[s] == 2) status[geo.slaveNode] = 2.0;  // sliding
    traction[geo.slaveNode] = geo.area > 0 ? norm(contact_.friction()->forces()[s]) / geo.area : 0.0;
  }
  return {force, pressure, gap, status, slip, traction};
}

std::vector<std::string> ContactReport::globalNames() const {
  return {"CONTACT_FORCE_TOTAL", "CONTACT_ACTIVE_NODES"};
}

std::vector<double> ContactReport::globalValues() const {
  double total = 0.0;
  for (double f : forces_) total += f;
  return {total, double(contact_.activeCount())};
}

std::vector<std::string> ContactReport::impactNames() const {
  std::vector<std::string> n;
  for (int p = 0; p < contact_.numPairs(); ++p) n.push_back(contact_.pair(p).name);
  return n;
}

std::vector<ImpactSample> ContactReport::impactSamples() const {
  std::vector<ImpactSample> out(contact_.numPairs());
  std::vector<char> first(contact_.numPairs(), 1);
  for (int s = 0; s < contact_.numConstraints(); ++s) {
    ImpactSample& o = out[contact_.constraints()[s].geometry.pair];
    o.force += forces_[s];
    if (first[contact_.constraints()[s].geometry.pair] || gaps_[s] < o.gap) {
      o.gap = gaps_[s];
      o.gapRate = rates_[s];
      first[contact_.constraints()[s].geometry.pair] = 0;
    }
  }
  for (ImpactSample& o : out) o.force = std::max(0.0, o.force);
  return out;
}

double obstaclePowerAt(const ContactManager& contact, const Vector& u) {
  bool obstacles = false;
  for (int p = 0; p < contact.numPairs(); ++p) obstacles = obstacles || contact.pair(p).hasObstacle;
  if (!obstacles) return 0.0;
  const std::vector<double> f = contact.forces(u);
  double p = 0.0;
  for (int s = 0; s < contact.numConstraints(); ++s) {
    const auto& geo = contact.constraints()[s].geometry;
    const PairDefinition& pair = contact.pair(geo.pair);
    if (pair.hasObstacle) p += f[s] * dot(geo.normal, pair.obstacle.velocity);
  }
  return p;
}

std::string ContactReport::progressNote() const {
  return std::to_string(contact_.activeCount()) + " contact nodes active";
}

}  // namespace choc
