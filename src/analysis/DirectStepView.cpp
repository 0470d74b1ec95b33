#include "analysis/DirectStepView.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include <array>
#include <map>

#include "core/Format.hpp"
#include "core/TimerScope.hpp"
#include "observers/SetMomentum.hpp"

namespace choc {

DirectStepView::DirectStepView(StructuralOperator& op, ContactReport* contact,
                                   const InteractionOutput* interactions, std::vector<Probe> probes,
                                   ObserverSet& outputs, Teuchos::StackedTimer* timer)
    : op_(op), contact_(contact), interactions_(interactions), probes_(std::move(probes)), outputs_(outputs), timer_(timer) {}

void DirectStepView::stepAccepted(const StepInfo& info, const Vector& u, const Vector& v,
                                    const Vector& a) {
  TimerScope ts(timer_, "Transient: output");
  info_ = info;
  u_ = &u;
  v_ = vScheme_ = &v;
  a_ = &a;
  differenceMassless(u, v, a);
  if (contact_) contact_->update(u, *v_, info.time);  // the reported velocity (massless DOFs differenced)
  outputs_.step(*this);
}

void DirectStepView::substepTaken(double time, const Vector& u, const Vector& v) {
  TimerScope ts(timer_, "Transient: output");
  if (contact_) contact_->update(u, v, time);
  outputs_.substep(*this, time);
}

// The massless DOFs' velocity and acceleration as differences of their displacement; with a
// normal contact mass, in the rotated DOFs where the normals are DOFs (physics/MasslessBasis.hpp).
void DirectStepView::differenceMassless(const Vector& u, const Vector& v, const Vector& a) {
  if (op_.mass().masslessDofs() == 0) return;
  const CrsMatrix* Q = op_.mass().masslessRotation().get();
  const bool first = !uPrev_;
  for (RCP<Vector>* x : {&vOut_, &aOut_, &uPrev_, &vPrev_, &work_})
    if (!*x) *x = rcp(new Vector(u.getMap()));
  auto toMassless = [&](const Vector& x, Vector& out) {
    if (Q) rotate(*Q, x, out, true);
    else out.assign(x);
  };
  toMassless(u, *work_);
  toMassless(v, *vOut_);
  toMassless(a, *aOut_);
  if (first) {
    uPrev_->assign(*work_);
    vPrev_->assign(*vOut_);
  }
  if (info_.step > 0 && info_.dt > 0) {
    const std::vector<char>& mask = op_.mass().masslessMask();
    auto ud = work_->getData();
    auto up = uPrev_->getData();
    auto vp = vPrev_->getData();
    auto vo = vOut_->getDataNonConst();
    auto ao = aOut_->getDataNonConst();
    for (size_t i = 0; i < mask.size(); ++i)
      if (mask[i]) {
        vo[i] = (ud[i] - up[i]) / info_.dt;
        ao[i] = (vo[i] - vp[i]) / info_.dt;
      }
  }
  uPrev_->assign(*work_);
  vPrev_->assign(*vOut_);
  if (Q) {
    work_->assign(*vOut_);
    rotate(*Q, *work_, *vOut_, false);
    work_->assign(*aOut_);
    rotate(*Q, *work_, *aOut_, false);
  }
  v_ = vOut_.get();
  a_ = aOut_.get();
}

void DirectStepView::archive(StateArchive& a, const StateVectors& vectors) const {
  const WorkIntegrals& work = op_.work();
  a.putVector("view/integrals", work.state());
  a.putVector("view/velocityUpdate", std::vector<double>{work.velocityUpdate});
  a.putVector("view/loadWork", work.loadWork.state());
  if (const Vector* uf = work.loadWork.followerDisplacement()) vectors.put(a, "view/followerDisplacement", *uf);
  if (uPrev_) {
    vectors.put(a, "view/uPrevious", *uPrev_);
    vectors.put(a, "view/vPrevious", *vPrev_);
  }
}

void DirectStepView::restore(const StateArchive& a, const StateVectors& vectors, RCP<const Map> map) {
  WorkIntegrals& work = op_.work();
  work.restore(a.getVector<double>("view/integrals", 4));
  if (a.has("view/velocityUpdate")) work.velocityUpdate = a.getVector<double>("view/velocityUpdate", 1)[0];
  work.loadWork.restore(a.getVector<double>("view/loadWork", work.loadWork.stateSize()));
  if (work.loadWork.hasFollowers() && a.has("view/followerDisplacement")) {
    Vector uf(map);
    vectors.get(a, "view/followerDisplacement", uf);
    work.loadWork.restoreFollowers(uf);
  }
  if (op_.mass().masslessDofs() == 0) return;
  for (RCP<Vector>* v : {&vOut_, &aOut_, &uPrev_, &vPrev_}) *v = rcp(new Vector(map));
  vectors.get(a, "view/uPrevious", *uPrev_);
  vectors.get(a, "view/vPrevious", *vPrev_);
}

StepPoint DirectStepView::point() const {
  StepPoint p;
  p.step = info_.step;
  p.time = info_.time;
  p.dt = info_.dt;
  p.last = info_.last;
  p.boundary = info_.boundary;
  p.nominal = info_.nominal;
  return p;
}

// Owned values summed across ranks; a set's momenta (observers/SetMomentum.hpp) once per set.
std::vector<double> DirectStepView::probeValues() const {
  std::vector<double> mine(probes_.size(), 0.0), vals(probes_.size(), 0.0);
  auto map = u_->getMap();
  std::map<std::string, std::array<double, 6>> momenta;
  for (size_t k = 0; k < probes_.size(); ++k) {
    const Probe& p = probes_[k];
    if (p.field == ProbeField::Momentum || p.field == ProbeField::AngularMomentum) {
      const std::string set = p.column.substr(0, p.column.find(':'));
      if (!momenta.count(set))
        momenta[set] = setMomentum(p, *u_, *vScheme_, [&](const Vector& x, Vector& y) { op_.mass().applyMass(x, y); });
      // The same on every rank already: rank 0's share of the sum below.
      if (map->getComm()->getRank() == 0)
        mine[k] = momenta[set][size_t((p.field == ProbeField::Momentum ? 0 : 3) + p.component)];
      continue;
    }
    if (probes_[k].dof < 0) continue;
    const LO l = map->getLocalElement(GO(probes_[k].dof));
    if (l == Teuchos::OrdinalTraits<LO>::invalid()) continue;
    const Vector& f = probes_[k].field == ProbeField::Displacement ? *u_
                      : probes_[k].field == ProbeField::Velocity   ? *v_
                                                                   : *a_;
    mine[k] = f.getData()[l];
  }
  if (!mine.empty())
    Teuchos::reduceAll<int, double>(*map->getComm(), Teuchos::REDUCE_SUM, int(mine.size()),
                                    mine.data(), vals.data());
  return vals;
}

// The operator's energies of the reported state, from the scheme's own velocity.
EnergyTerms DirectStepView::energies() {
  return EnergyTerms(op_.energies(*u_, *vScheme_, *a_, info_.time, info_.dt, info_.substep));
}

void DirectStepView::fields(Vector& u, Vector& v, Vector& a) const {
  u.assign(*u_);
  v.assign(*v_);
  a.assign(*a_);
}

void DirectStepView::elementFields(std::vector<std::vector<double>>& values) const {
  op_.internalForce().elementFields(*u_, values);
}

std::string DirectStepView::stepNote() const {
  if (info_.step > 0 && info_.newton.activeSetIterations == 0) return "explicit";  // no solve
  return format("Newton %d, active-set passes %d", info_.newton.iterations,
                info_.newton.activeSetIterations);
}

}  // namespace choc
