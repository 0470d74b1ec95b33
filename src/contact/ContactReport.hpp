// What the contact of a direct transient reports at a recorded state: per pair the total
// normal force, the smallest gap and the contact area (the tributary areas of the active slave
// nodes; history '<pair>:force', '<pair>:gap', '<pair>:area'), per slave node
// the force, pressure, gap, status and tangential slip (Exodus CONTACT_FORCE, CONTACT_PRESSURE,
// CONTACT_GAP, CONTACT_STATUS, CONTACT_SLIP) and in total the force and the number of active nodes (Exodus globals).
// With friction also, per pair, the size of the summed friction force and the friction work
// ('<pair>:tangential_force', '<pair>:friction_work'), per node the tangential traction
// (CONTACT_TANGENTIAL_TRACTION) and CONTACT_STATUS 2 for a sliding node (1: sticking).
// update(u, t) evaluates the forces and gaps once (collective); the rest reads them, except
// nodalFields(), which gathers the slips (collective: called on every rank, as the Exodus
// writer does).
#pragma once
#include "contact/ContactManager.hpp"
#include "output/InteractionOutput.hpp"

namespace choc {

class ContactReport : public InteractionOutput {
 public:
  ContactReport(const ContactManager& contact, int numMeshNodes)
      : contact_(contact), numNodes_(numMeshNodes) {}
  void update(const Vector& u, const Vector& v, double t);

  std::vector<std::string> historyColumns() const override;
  std::vector<double> historyValues() const override;
  std::vector<std::string> nodalFieldNames() const override;
  std::vector<std::vector<double>> nodalFields() const override;
  std::vector<std::string> globalNames() const override;
  std::vector<double> globalValues() const override;
  std::string progressNote() const override;
  // Per pair: the total normal force, the smallest gap and that node's gap rate.
  std::vector<std::string> impactNames() const override;
  std::vector<ImpactSample> impactSamples() const override;

 private:
  const ContactManager& contact_;
  int numNodes_;
  std::vector<double> forces_, gaps_, rates_;
  const Vector* u_ = nullptr;  // the state of the last update
  double time_ = 0.0;
};

}  // namespace choc
