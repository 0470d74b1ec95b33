// The contact part of an analysis' input: its parameters ('Contact' and 'Contact Mass'), the
// settings read from them, and the factory from settings to a contact manager with its
// enforcement method. The analysis never picks a method or reads a contact key itself.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "contact/ContactManager.hpp"

namespace choc {

// Declares 'Contact' (method, pairs, tolerances) and 'Contact Mass' in an analysis' list.
void declareContactParameters(Teuchos::ParameterList& analysis);

// The contact methods; what an analysis needs to know of one, it asks (ContactSettings).
enum class ContactMethodKind { None, Lagrange, Penalty, Continuous };
const char* contactMethodName(ContactMethodKind m);

struct ContactSettings {
  ContactMethodKind method = ContactMethodKind::None;
  double penaltyStiffness = 0, augmentation = 0, gapTolerance = 0;
  double tangentialStiffness = 0;  // 0: automatic (see 'Tangential Stiffness')
  int maxActiveSetIterations = 20;
  std::string statusUpdate = "auto";  // 'Status Update': auto, each correction, converged solve
  std::vector<PairDefinition> pairs;
  bool redistributeMass = false;  // 'Contact Mass' = redistributed, or auto (implicit schemes)
  bool massIsAutomatic = false;   // 'Contact Mass' = auto: may fall back to standard
  bool velocityUpdate = false;    // 'Contact Mass' = velocity update: standard mass, v projected after each step
  bool normalMass = false;        // 'Contact Mass' = normal: the contact nodes massless along their normals
  std::string path;               // "Analyses/<name>", for messages
  bool enabled() const { return method != ContactMethodKind::None; }
  bool hasMultipliers() const {
    return method == ContactMethodKind::Lagrange || method == ContactMethodKind::Continuous;
  }
  // Pressure unknowns, which an explicit scheme cannot solve for.
  bool hasPressureUnknowns() const { return method == ContactMethodKind::Continuous; }
  // An explicit scheme enforces the multipliers by forward increments.
  bool forwardIncrementsWhenExplicit() const { return method == ContactMethodKind::Lagrange; }
  std::string methodName() const { return contactMethodName(method); }
  // Multipliers that an implicit iterative solve eliminates: every pair against a rigid obstacle
  // (ContactCondensation, node by node), or Lagrange contact on any pairs (ContactProjection);
  // with or without friction.
  bool condensable() const {
    if (!hasMultipliers() || pairs.empty()) return false;
    bool obstacles = true;
    for (const auto& p : pairs) obstacles = obstacles && p.hasObstacle;
    return obstacles || method == ContactMethodKind::Lagrange;
  }
  // The first pair with a friction coefficient, or null.
  const PairDefinition* frictionPair() const {
    for (const auto& p : pairs)
      if (p.friction > 0) return &p;
    return nullptr;
  }
};

// Reads the validated analysis list; throws InputError for a method without pairs or a
// redistributed mass without contact.
ContactSettings readContactSettings(const Teuchos::ParameterList& analysis, const std::string& file,
                                    const std::string& analysisPath);

// The manager of the settings' pairs on the model (null when the method is None). Throws
// InputError naming the pair's parameter for a side set the mesh lacks or a pairing failure.
// axisymmetric: slave areas of whole rings (the pressure output).
std::unique_ptr<ContactManager> makeContactManager(const ContactSettings& s, const Mesh& mesh,
                                                   const DofMap& dofs, RCP<const Map> map,
                                                   const std::string& file, bool axisymmetric = false);

}  // namespace choc
