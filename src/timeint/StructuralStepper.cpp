#include "timeint/StructuralStepper.hpp"

#include <Tpetra_Vector.hpp>

#include <cstdio>

#include "core/Log.hpp"

namespace choc {

StructuralStepper::StructuralStepper(SecondOrderOperator& op, TransientSettings settings)
    : op_(op), s_(std::move(settings)) {
  auto map = op_.map();
  for (RCP<Vector>* v : {&u_, &v_, &a_}) *v = rcp(new Vector(map));
}

void StructuralStepper::setInitialState(const Vector& u, const Vector& v) {
  u_->assign(u);
  v_->assign(v);
}

void StructuralStepper::notify(const StepInfo& info) {
  for (StepObserver* o : observers_) o->stepAccepted(info, *u_, *v_, *a_);
}

void StructuralStepper::notifySubstep(double t) {
  for (StepObserver* o : observers_) o->substepTaken(t, *u_, *v_);
}

std::string StructuralStepper::checkValidity(const Vector& u, double t) {
  const ElementValidity v = op_.validity(u);
  if (!v.warning.empty() && !validityWarned_) {
    validityWarned_ = true;
    char at[64];
    std::snprintf(at, sizeof at, ": at t = %.6e s: ", t);
    log() << "choc: warning: " << s_.label << at << v.warning << "\n";
  }
  return v.failure;
}

void StructuralStepper::archiveState(StateArchive& a, const StateVectors& vectors) const {
  vectors.put(a, "driver/u", *u_);
  vectors.put(a, "driver/v", *v_);
  vectors.put(a, "driver/a", *a_);
  op_.archive(a);
}

void StructuralStepper::restoreState(const StateArchive& a, const StateVectors& vectors) {
  vectors.get(a, "driver/u", *u_);
  vectors.get(a, "driver/v", *v_);
  vectors.get(a, "driver/a", *a_);
  op_.restore(a);
  op_.commit();
}

TransientSummary StructuralStepper::run(Vector& u, Vector& v, const StepLoop::Resume* resume) {
  if (!resume) setInitialState(u, v);
  StepLoop loop(*this, TimeGrid(s_.startTime, s_.endTime, s_.timeStep));
  const TransientSummary sum = loop.run(resume);
  u.assign(*u_);
  v.assign(*v_);
  return sum;
}

}  // namespace choc
