#pragma once
// Shock links of a modal transient: each link is evaluated in physical space at its two
// nodes only (positions X + Phi q, velocities Phi q'), and its force is projected back on the
// basis (f_q += Phi^T F). The per-step cost is O(modes x link nodes), independent of the mesh.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "physics/ModalBasis.hpp"
#include "physics/ShockLinks.hpp"
#include "physics/Model.hpp"
#include "timeint/ModalIntegrator.hpp"


namespace choc {

class ModalLinks : public ModalForce, public ShockLinkSet {
 public:
  // The links with their rows of the basis (the DX, DY, DZ rows at their nodes).
  ModalLinks(std::vector<ShockLink> links, const Model& model, const ModalBasis& basis);
  void evaluate(double t, const std::vector<double>& q, const std::vector<double>& v, double dt,
                std::vector<double>& f) override;
  bool nearContact(double dt) const override;
  void project(double h, std::vector<double>& q, std::vector<double>& v) override;
  const std::vector<double>* constraintForce() const override {
    return hasRigid_ ? &constraintForce_ : nullptr;
  }
  // Highest circular frequency the links add to the basis (bound: K * sum_k |dphi_k|^2 with K
  // the larger of the normal and tangential stiffnesses)
  // and the largest link damping ratio, for the critical step.
  double linkOmega2Bound() const;
  double linkDampingRatioBound() const;
  void archive(StateArchive& a) const override;
  // The constraint force of the last project() expressed on another basis (a restart on a
  // basis recomputed on another number of ranks).
  void setConstraintForce(std::vector<double> f) { constraintForce_ = std::move(f); }
  void restore(const StateArchive& a) override;

 private:
  Vec3 relative(size_t i, const std::vector<double>& x, bool position) const;
  // Generalized direction of a unit force on link i's node 2 along m (and its opposite on
  // node 1).
  void generalizedDirection(size_t i, const Vec3& m, std::vector<double>& b) const;
  // Per link: the DX, DY, DZ rows of the basis at its nodes ([3 * modes] each; zeros for a
  // fixed obstacle).
  std::vector<std::vector<double>> phi1_, phi2_;
  int modes_ = 0;
  bool hasRigid_ = false;
  std::vector<double> constraintForce_;  // B^T lambda of the last project()
};

}  // namespace choc
