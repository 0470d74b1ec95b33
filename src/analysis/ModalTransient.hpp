// Modal transient analysis: the generalized system of a modal basis computed earlier in the
// same input (diagonal modal mass and stiffness, modal damping, rigid-body modes undamped),
// initial fields projected on the basis, nonlinear shock links evaluated at their nodes,
// explicit integration with a critical-step check that includes the link stiffness.
#pragma once
#include "analysis/Analysis.hpp"

namespace choc {

class ModalTransient : public Analysis {
 public:
  using Analysis::Analysis;
  static Teuchos::ParameterList parameters();
  void run(RunContext& ctx) override;
};

}  // namespace choc
