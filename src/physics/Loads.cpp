#include "physics/Loads.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <Tpetra_Vector.hpp>

#include "fem/Quadrature.hpp"
#include "fem/ShapeFunctions.hpp"

namespace choc {

double rampFactor(double rampTime, double t) {
  if (rampTime <= 0.0 || t >= rampTime) return 1.0;
  return std::max(t, 0.0) / rampTime;
}

double LoadGroup::factor(double t) const { return rampFactor(rampTime, t); }

void Loads::add(LoadGroup g) {
  for (LoadGroup& h : groups_)
    if (h.rampTime == g.rampTime) {
      h.force->update(1.0, *g.force, 1.0);
      h.name += ", " + g.name;
      return;
    }
  groups_.push_back(std::move(g));
}

void Loads::subtractFrom(double t, Vector& out) const {
  for (const LoadGroup& g : groups_) {
    const double f = g.factor(t);
    if (f != 0.0) out.update(-f, *g.force, 1.0);
  }
}

double LoadWork::update(const Vector& u, double t) {
  if (!loads_) return 0.0;
  const auto& groups = loads_->groups();
  std::vector<double> p(groups.size());
  for (size_t k = 0; k < groups.size(); ++k) p[k] = groups[k].force->dot(u);
  if (started_)
    for (size_t k = 0; k < groups.size(); ++k)
      work_ += 0.5 * (groups[k].factor(time_) + groups[k].factor(t)) * (p[k] - projection_[k]);
  if (hasFollowers()) {
    if (f_.is_null()) f_ = rcp(new Vector(u.getMap()));
    followerForce(u, t, *f_);
    if (started_ && !uPrev_.is_null()) {
      fPrev_->update(1.0, *f_, 1.0);  // f_n + f_n+1
      uPrev_->update(1.0, u, -1.0);   // u_n+1 - u_n
      work_ += 0.5 * fPrev_->dot(*uPrev_);
    }
    if (uPrev_.is_null()) uPrev_ = rcp(new Vector(u.getMap())), fPrev_ = rcp(new Vector(u.getMap()));
    uPrev_->assign(u);
    fPrev_->assign(*f_);
  }
  started_ = true;
  time_ = t;
  projection_ = std::move(p);
  return work_;
}

std::vector<double> LoadWork::state() const {
  std::vector<double> s{started_ ? 1.0 : 0.0, work_, time_};
  s.insert(s.end(), projection_.begin(), projection_.end());
  if (!started_) s.resize(stateSize(), 0.0);
  return s;
}

void LoadWork::followerForce(const Vector& u, double t, Vector& out) const {
  out.putScalar(0.0);
  for (const auto& f : loads_->followers()) f->addForce(u, t, out);
}

void LoadWork::restoreFollowers(const Vector& u) {
  uPrev_ = rcp(new Vector(u, Teuchos::Copy));
  fPrev_ = rcp(new Vector(u.getMap()));
  followerForce(u, time_, *fPrev_);
}

void LoadWork::restore(const std::vector<double>& s) {
  if (s.size() != stateSize()) throw std::invalid_argument("load work: the checkpoint has another number of load groups");
  started_ = s[0] != 0.0;
  work_ = s[1];
  time_ = s[2];
  projection_.assign(s.begin() + 3, s.end());
}

std::map<int, Point3> pressureForces(const std::vector<Face>& faces, double p, bool axisymmetric) {
  PressureField field;
  field.value = p;
  return pressureForces(faces, field, axisymmetric);
}

std::map<int, Point3> pressureForces(const std::vector<Face>& faces, const PressureField& p, bool axisymmetric) {
  std::map<int, Point3> forces;
  for (const Face& f : faces) {
    // Edges: 3-point Gauss, exact for LINE3 shape functions times a ring.
    const QuadratureRule& rule = f.edgeNodes ? gaussBoxRule(1, 3) : massRule(f.shape);
    for (int k = 0; k < rule.size(); ++k) {
      const FacePoint q = evaluateFace(f, rule.points[k][0], rule.points[k][1]);
      const double ring = axisymmetric && f.edgeNodes ? 2.0 * M_PI * q.x[0] : 1.0;
      const Point3 nA = cross(q.dxi, q.deta);  // outward normal times the area element
      const double w = -p.at(q.x) * rule.weights[k] * ring;
      for (size_t a = 0; a < f.nodes.size(); ++a) {
        Point3& fa = forces[f.nodes[a]];
        for (int c = 0; c < 3; ++c) fa[c] += w * q.N[a] * nA[c];
      }
    }
  }
  return forces;
}

}  // namespace choc
