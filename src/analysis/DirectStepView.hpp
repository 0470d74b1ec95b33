// The direct transient's state as the output observers see it: hung on the driver's step
// hook, it evaluates the contact report once per accepted step, then calls the observers.
// Energies come from the structural operator (with the damping, obstacles' and loads' work it
// integrates; this view archives them in a checkpoint). Massless DOFs (redistributed contact
// mass) have no inertia to integrate: their Newmark velocity and acceleration only close the
// scheme's relations and oscillate after a velocity jump, so the outputs (history, Exodus)
// give them the backward differences of their displacement, v = (u_{n+1} - u_n)/dt and
// a = (v_{n+1} - v_n)/dt; the energies use the scheme's own fields.
#pragma once
#include <vector>

#include <Teuchos_StackedTimer.hpp>

#include "contact/ContactReport.hpp"
#include "observers/Probes.hpp"
#include "observers/TransientObserver.hpp"
#include "physics/StructuralOperator.hpp"
#include "restart/StateVectors.hpp"
#include "timeint/StructuralStepper.hpp"

namespace choc {

class DirectStepView : public TransientView, public StepObserver {
 public:
  // contact may be null; interactions: what the output reports (the contact report, the
  // links, both, or null); timer (may be null) times the output under "Transient: output".
  DirectStepView(StructuralOperator& op, ContactReport* contact,
                   const InteractionOutput* interactions, std::vector<Probe> probes,
                   ObserverSet& outputs, Teuchos::StackedTimer* timer);

  void stepAccepted(const StepInfo& info, const Vector& u, const Vector& v, const Vector& a) override;
  void substepTaken(double time, const Vector& u, const Vector& v) override;

  StepPoint point() const override;
  std::vector<double> probeValues() const override;
  EnergyTerms energies() override;
  const InteractionOutput* interactions() const override { return interactions_; }
  void fields(Vector& u, Vector& v, Vector& a) const override;
  std::vector<std::string> elementFieldNames() const override { return op_.internalForce().elementFieldNames(); }
  std::vector<char> elementFieldBlocks() const override { return op_.internalForce().elementFieldBlocks(); }
  void elementFields(std::vector<std::vector<double>>& values) const override;
  std::string stepNote() const override;

  // The operator's work integrals (damping, obstacle and load work) and the previous
  // reported fields of massless DOFs, for a checkpoint (collective), and back.
  void archive(StateArchive& a, const StateVectors& vectors) const;
  void restore(const StateArchive& a, const StateVectors& vectors, RCP<const Map> map);

 private:
  StructuralOperator& op_;
  ContactReport* contact_;
  const InteractionOutput* interactions_;
  std::vector<Probe> probes_;
  ObserverSet& outputs_;
  Teuchos::StackedTimer* timer_;
  StepInfo info_;
  void differenceMassless(const Vector& u, const Vector& v, const Vector& a);
  const Vector *u_ = nullptr, *v_ = nullptr, *a_ = nullptr;  // the reported fields
  const Vector* vScheme_ = nullptr;                           // the scheme's velocity
  // Reported fields and the previous step's (uPrev_, vPrev_ in the massless DOFs' rotated
  // coordinates with a normal contact mass), and a work vector.
  RCP<Vector> vOut_, aOut_, uPrev_, vPrev_, work_;
};

}  // namespace choc
