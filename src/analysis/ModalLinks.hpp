#pragma once
// Shock links of a modal transient: each link is evaluated in physical space at its two
// nodes only (positions X + Phi q, velocities Phi q'), and its force is projected back on the
// basis (f_q += Phi^T F). The per-step cost is O(modes x link nodes), independent of the mesh.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "analysis/Analysis.hpp"
#include "contact/ShockLaw.hpp"
#include "timeint/ModalIntegrator.hpp"


namespace choc {

void declareShockLinks(Teuchos::ParameterList& analysisParameters);

struct ModalLink {
  std::string name;
  int node1 = -1, node2 = -1;  // node2 = -1: fixed obstacle at node 1's initial position
  ShockLawParameters law;
  Vec3 x1{}, x2{};                                 // initial positions
  std::vector<double> phi1, phi2;                  // [3 * modes]: rows of DX, DY, DZ
  ShockLawState state;
  ShockResponse last;
};

class ModalLinks : public ModalForce {
 public:
  ModalLinks(const Teuchos::ParameterList& analysisParameters, const Model& model,
             const ModalBasis& basis, const std::string& analysisPath);
  void evaluate(double t, const std::vector<double>& q, const std::vector<double>& v, double dt,
                std::vector<double>& f) override;
  bool nearContact(double dt) const override;
  void project(double h, std::vector<double>& q, std::vector<double>& v) override;
  const std::vector<double>* constraintForce() const override {
    return hasRigid_ ? &constraintForce_ : nullptr;
  }
  const std::vector<ModalLink>& links() const { return links_; }
  // Highest circular frequency the links add to the basis (bound: K * sum_k (dphi_k . m)^2)
  // and the largest link damping ratio, for the critical step.
  double linkOmega2Bound() const;
  double linkDampingRatioBound() const;
  double springEnergy() const;
  double dissipatedEnergy() const { return linkDissipated_; }

 private:
  Vec3 relative(const ModalLink& l, const std::vector<double>& x, bool position) const;
  // Generalized direction of a unit force on node 2 along m (and its opposite on node 1).
  void generalizedDirection(const ModalLink& l, const Vec3& m, std::vector<double>& b) const;
  std::vector<ModalLink> links_;
  int modes_ = 0;
  double linkDissipated_ = 0.0;
  std::vector<double> lastGapRate_;
  bool hasRigid_ = false;
  std::vector<double> constraintForce_;  // B^T lambda of the last project()
};

}  // namespace choc
