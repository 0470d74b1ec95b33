// The direct transient's state as the output observers see it: hung on the driver's step
// hook, it evaluates the contact report once per accepted step, then calls the observers.
// Energies come from the structural operator; the Rayleigh damping work is integrated here
// by the trapezoidal rule, the loads' work is exact.
#pragma once
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "contact/ContactReport.hpp"
#include "observers/Probes.hpp"
#include "observers/TransientObserver.hpp"
#include "physics/StructuralOperator.hpp"
#include "timeint/TransientDriver.hpp"

namespace choc {

class ImplicitStepView : public TransientView, public StepObserver {
 public:
  // contact may be null; timer (may be null) times the output under "Transient: output".
  ImplicitStepView(const StructuralOperator& op, ContactReport* contact, std::vector<Probe> probes,
                   ObserverSet& outputs, Teuchos::StackedTimer* timer);

  void stepAccepted(const StepInfo& info, const Vector& u, const Vector& v, const Vector& a) override;

  StepPoint point() const override;
  std::vector<double> probeValues() const override;
  EnergyTerms energies() override;
  const InteractionOutput* interactions() const override { return contact_; }
  void fields(Vector& u, Vector& v, Vector& a) const override;
  std::string stepNote() const override;

 private:
  const StructuralOperator& op_;
  ContactReport* contact_;
  std::vector<Probe> probes_;
  ObserverSet& outputs_;
  Teuchos::StackedTimer* timer_;
  StepInfo info_;
  const Vector *u_ = nullptr, *v_ = nullptr, *a_ = nullptr;
  RCP<Vector> u0_;
  double dissipated_ = 0.0, lastPower_ = 0.0;
};

}  // namespace choc
