#include "analysis/DirectStepView.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include <array>
#include <map>

#include "core/Format.hpp"
#include "core/TimerScope.hpp"
#include "observers/SetMomentum.hpp"

namespace choc {

DirectStepView::DirectStepView(const StructuralOperator& op, ContactReport* contact,
                                   const InteractionOutput* interactions, std::vector<Probe> probes,
                                   ObserverSet& outputs, Teuchos::StackedTimer* timer)
    : op_(op), contact_(contact), interactions_(interactions), probes_(std::move(probes)), outputs_(outputs), timer_(timer), loadWork_(op.loads()) {}

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

void DirectStepView::differenceMassless(const Vector& u, const Vector& v, const Vector& a) {
  if (op_.masslessDofs() == 0) return;
  if (!vOut_) {
    vOut_ = rcp(new Vector(v, Teuchos::Copy));
    aOut_ = rcp(new Vector(a, Teuchos::Copy));
    uPrev_ = rcp(new Vector(u, Teuchos::Copy));
    vPrev_ = rcp(new Vector(v, Teuchos::Copy));
  } else {
    vOut_->assign(v);
    aOut_->assign(a);
  }
  if (info_.step > 0 && info_.dt > 0) {
    const std::vector<char>& mask = op_.masslessMask();
    auto ud = u.getData();
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
  uPrev_->assign(u);
  vPrev_->assign(*vOut_);
  v_ = vOut_.get();
  a_ = aOut_.get();
}

void DirectStepView::archive(StateArchive& a, const StateVectors& vectors) const {
  a.putVector("view/integrals", std::vector<double>{dissipated_, lastPower_, obstacleWork_, lastObstaclePower_});
  a.putVector("view/loadWork", loadWork_.state());
  if (const Vector* uf = loadWork_.followerDisplacement()) vectors.put(a, "view/followerDisplacement", *uf);
  if (uPrev_) {
    vectors.put(a, "view/uPrevious", *uPrev_);
    vectors.put(a, "view/vPrevious", *vPrev_);
  }
}

void DirectStepView::restore(const StateArchive& a, const StateVectors& vectors, RCP<const Map> map) {
  const std::vector<double> w = a.getVector<double>("view/integrals", 4);
  dissipated_ = w[0];
  lastPower_ = w[1];
  obstacleWork_ = w[2];
  lastObstaclePower_ = w[3];
  loadWork_.restore(a.getVector<double>("view/loadWork", loadWork_.stateSize()));
  if (loadWork_.hasFollowers() && a.has("view/followerDisplacement")) {
    Vector uf(map);
    vectors.get(a, "view/followerDisplacement", uf);
    loadWork_.restoreFollowers(uf);
  }
  if (op_.masslessDofs() == 0) return;
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
        momenta[set] = setMomentum(p, *u_, *vScheme_, [&](const Vector& x, Vector& y) { op_.massTimes(x, y); });
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

EnergyTerms DirectStepView::energies() {
  EnergyTerms e;
  e.kinetic = op_.kineticEnergy(*vScheme_);
  e.strain = op_.strainEnergy(*u_);
  e.contact = op_.contactEnergy(*u_) + (op_.links() ? op_.links()->springEnergy() : 0.0);
  const double power = op_.dampingPower(*vScheme_, e.kinetic);
  dissipated_ += 0.5 * info_.dt * (lastPower_ + power);
  lastPower_ = power;
  e.dissipated = dissipated_ + (op_.links() ? op_.links()->dissipatedEnergy() : 0.0) +
                 op_.frictionDissipation() + op_.internalForce().dissipatedWork();
  e.plastic = op_.internalForce().dissipatedWork();
  e.hourglass = op_.internalForce().hourglassEnergy(*u_);
  // Work of moving obstacles: trapezoidal rule on their power.
  const double obstaclePower = contact_ ? contact_->obstaclePower() : 0.0;
  obstacleWork_ += 0.5 * info_.dt * (lastObstaclePower_ + obstaclePower);
  lastObstaclePower_ = obstaclePower;
  e.external = loadWork_.update(*u_, info_.time) + obstacleWork_;
  // Central differences: the part of the energy the scheme's conserved energy leaves out,
  // (h^2/8) a^T M a = (h^2/4) x "the kinetic energy of a" (EnergyTerms::shadow).
  if (info_.substep > 0) e.shadow = 0.25 * info_.substep * info_.substep * op_.kineticEnergy(*a_);
  return e;
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
