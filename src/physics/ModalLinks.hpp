#pragma once
// Shock links of a modal transient: each link is evaluated in physical space at its two
// nodes only (positions X + Phi q, velocities Phi q'), and its force is projected back on the
// basis (f_q += Phi^T F). The per-step cost is O(modes x link nodes), independent of the mesh.
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/ShockLaw.hpp"
#include "output/InteractionOutput.hpp"
#include "physics/ModalBasis.hpp"
#include "physics/Model.hpp"
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

// The links of an analysis list ('Shock Links'), resolved on the model: nodes, shapes, laws
// (no basis yet: phi1, phi2 empty). Throws InputError naming the link's parameter.
std::vector<ModalLink> readShockLinks(const Teuchos::ParameterList& analysisParameters,
                                      const Model& model, const std::string& analysisPath);
// '<link>:force', '<link>:gap', '<link>:status' per link.
std::vector<std::string> shockLinkColumns(const std::vector<ModalLink>& links);

class ModalLinks : public ModalForce, public InteractionOutput {
 public:
  // The links with their rows of the basis (the DX, DY, DZ rows at their nodes).
  ModalLinks(std::vector<ModalLink> links, const Model& model, const ModalBasis& basis);
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
  void archive(StateArchive& a) const override;
  // The constraint force of the last project() expressed on another basis (a restart on a
  // basis recomputed on another number of ranks).
  void setConstraintForce(std::vector<double> f) { constraintForce_ = std::move(f); }
  void unarchive(const StateArchive& a) override;

  // Output: force, gap and status per link (history and Exodus globals).
  std::vector<std::string> historyColumns() const override { return shockLinkColumns(links_); }
  std::vector<double> historyValues() const override;
  std::vector<std::string> globalNames() const override;
  std::vector<double> globalValues() const override { return historyValues(); }
  std::string progressNote() const override;
  std::vector<std::string> impactNames() const override;
  std::vector<ImpactSample> impactSamples() const override;

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
  std::vector<double> gapRate_, slipSpeed_;  // along the shape's normal, at the last evaluate()
};

}  // namespace choc
