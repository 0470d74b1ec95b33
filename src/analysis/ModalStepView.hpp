// The modal transient's state as the output observers see it: probes rebuilt from the
// basis rows at their DOFs, energies of the generalized system (velocities synchronised with
// the displacements), the shock links as interactions, physical fields expanded on the basis
// only when Exodus asks for them.
#pragma once
#include <vector>

#include "observers/Probes.hpp"
#include "observers/TransientView.hpp"
#include "physics/ModalBasis.hpp"
#include "physics/ModalLinks.hpp"
#include "timeint/ModalIntegrator.hpp"

namespace choc {

struct ModalProbes {
  std::vector<Probe> probes;
  std::vector<double> rows;  // [probe][mode]: the basis at the probe's DOF
};

class ModalStepView : public TransientView {
 public:
  ModalStepView(const ModalState& state, const ModalIntegrator& integrator, const ModalLinks& links,
                const ModalBasis& basis, std::vector<double> omega2, ModalProbes probes,
                bool symplecticEuler);
  void at(long long step, double dt, bool last);  // the state now holds this step
  void setSubstep(double h) { substep_ = h; }     // the scheme's (sub-)step, for the energy

  StepPoint point() const override { return point_; }
  std::vector<double> probeValues() const override;
  EnergyTerms energies() override;
  const InteractionOutput* interactions() const override { return &links_; }
  void fields(Vector& u, Vector& v, Vector& a) const override;
  std::string stepNote() const override { return ""; }

 private:
  const ModalState& state_;
  const ModalIntegrator& integrator_;
  const ModalLinks& links_;
  const ModalBasis& basis_;
  std::vector<double> w2_;
  ModalProbes probes_;
  bool symplecticEuler_;
  StepPoint point_;
  double substep_ = 0.0;
};

}  // namespace choc
