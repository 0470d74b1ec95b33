#pragma once
// Shock links (DIS_CHOC): their input ('Shock Links' of a modal or a direct transient), and
// what every set of links reports whatever integrates it: history columns, Exodus globals,
// impact samples, energies, and the state a checkpoint carries. The modal transient evaluates
// them on its basis (physics/ModalLinks), the direct transient on the nodal unknowns
// (physics/DirectLinks); both with the same law (contact/ShockLaw).
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/ShockLaw.hpp"
#include "output/InteractionOutput.hpp"
#include "physics/Model.hpp"
#include "restart/StateArchive.hpp"

namespace choc {

void declareShockLinks(Teuchos::ParameterList& analysisParameters);

struct ShockLink {
  std::string name;
  std::string path;  // of its entry in the input, e.g. 'Analyses/run/Shock Links/stop'
  int node1 = -1, node2 = -1;  // node2 = -1: fixed obstacle at x2 ('Obstacle Origin')
  ShockLawParameters law;
  Vec3 x1{}, x2{};  // initial positions (x2: the fixed obstacle's origin when node2 = -1)
  ShockLawState state;
  ShockResponse last;
};

// The links of an analysis list ('Shock Links'), resolved on the model: nodes, shapes, laws.
// Throws InputError naming the link's parameter.
std::vector<ShockLink> readShockLinks(const Teuchos::ParameterList& analysisParameters,
                                      const Model& model, const std::string& analysisPath);
// '<link>:force', '<link>:gap', '<link>:status' per link (status 0 open, 1 closed, 2 closed and
// sliding), and for a link with tangential terms ':tangential_force', ':slip_velocity',
// ':friction_work'.
std::vector<std::string> shockLinkColumns(const std::vector<ShockLink>& links);

class ShockLinkSet : public InteractionOutput {
 public:
  explicit ShockLinkSet(std::vector<ShockLink> links);
  const std::vector<ShockLink>& links() const { return links_; }
  double springEnergy() const;
  // The dashpots' dissipation and the friction work of every link.
  double dissipatedEnergy() const;
  // Link i's friction work: the work of its tangential force less what its stick spring holds.
  double frictionWork(size_t i) const;

  // Output: force, gap and status per link (history and Exodus globals).
  std::vector<std::string> historyColumns() const override { return shockLinkColumns(links_); }
  std::vector<double> historyValues() const override;
  std::vector<std::string> globalNames() const override;
  std::vector<double> globalValues() const override { return historyValues(); }
  std::string progressNote() const override;
  std::vector<std::string> impactNames() const override;
  std::vector<ImpactSample> impactSamples() const override;

 protected:
  // Records link i's gap rate and slip speed at relative velocity w (open or closed), for the
  // impact statistics.
  void recordKinematics(size_t i, const Vec3& d, const Vec3& w);
  // Advances the dissipated energy by link i's dashpot power over dt (trapezoidal rule), with
  // link i's committed response and relative velocity w; wasClosed: its state before.
  void accumulateDissipation(size_t i, bool wasClosed, const Vec3& w, double dt);
  // Advances link i's tangential work by the trapezoidal rule on the power -Ft . w of its
  // committed response.
  void accumulateTangentialPower(size_t i, const Vec3& w, double dt);
  void addTangentialWork(size_t i, double work) { tangentialWork_[i] += work; }
  void archiveLinks(StateArchive& a) const;
  void restoreLinks(const StateArchive& a);

  std::vector<ShockLink> links_;
  double dissipated_ = 0.0;
  std::vector<double> lastGapRate_;          // along the force, at the last committed state
  std::vector<double> tangentialWork_, lastTangentialPower_;  // per link
  std::vector<double> gapRate_, slipSpeed_;  // along the shape's normal, at the last evaluation
};

}  // namespace choc
