// The blocks declared rigid ('Model/Blocks/<name>/Rigid'), one body each (rigid/RigidBody.hpp):
// their nodes' rows of the model's vectors, the forces on them summed over the ranks into each
// body's resultant and moment, the bodies advanced by central differences' velocity Verlet and
// their nodes placed where the bodies put them (docs/theory/rigid-bodies.md, section 4).
#pragma once
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include "contact/ContactBodies.hpp"
#include "output/InteractionOutput.hpp"
#include "rigid/RigidBody.hpp"
#include "timeint/RigidMotion.hpp"

namespace choc {

class Model;
class StateArchive;

class RigidBodies : public RigidMotion, public ContactBodies, public InteractionOutput {
 public:
  // The rigid blocks of the model, then its kinematic couplings (none: empty()); lumpedMass the model's lumped mass diagonal,
  // which weighs the nodes' initial velocities. Throws InputError for a rigid block outside 3D,
  // sharing nodes with another block, or with a node whose components are not all unknowns.
  RigidBodies(const Model& model, const Vector& lumpedMass);
  bool empty() const { return bodies_.empty(); }
  const std::vector<RigidBody>& bodies() const { return bodies_; }
  // x's rows of the bodies' nodes set to 0 (their inverse mass: central differences leave them alone).
  void zeroRows(Vector& x) const;
  double kineticEnergy() const;
  // Gravity g [m/s^2] on every body: m g at its centre, from the next forces on.
  void setGravity(const Vec3& g) { gravity_ = g; }
  // The work of the holds and of gravity on the bodies since the start [J] (external work).
  double externalWork() const;

  void start(const Vector& u, Vector& v) override;
  void accelerate(const Vector& r, Vector& a) override;
  void predict(double h, double factor, const Vector& r, Vector& uStar) override;
  RigidContactBodies describe(const std::vector<GO>& dofs) const override;
  void drift(double h, Vector& u, Vector& vHalf) override;
  void kick(double h, const Vector& r, Vector& v, Vector& a) override;

  void archive(StateArchive& a) const;
  void restore(const StateArchive& a);

  // The history of each body '<block>': its centre X Y Z, velocity VX VY VZ, rotation vector
  // RX RY RZ (since the start), angular velocity WX WY WZ, momentum PX PY PZ, angular momentum
  // about the origin LX LY LZ, kinetic energy, and the resultant FX FY FZ and moment MX MY MZ
  // (about the centre) of the forces on it; a held body also reactionX..Z and reactionMX..MZ,
  // the force and moment its hold applies.
  std::vector<std::string> historyColumns() const override;
  std::vector<double> historyValues() const override;
  std::vector<std::string> globalNames() const override { return {}; }
  std::vector<double> globalValues() const override { return {}; }
  std::string progressNote() const override { return ""; }

 private:
  struct Row {
    int body;
    Vec3 X;   // the node's reference position
    Vec3 xi;  // its body-frame coordinates: x = centre + R xi
    int component;
    LO row;  // local row of the model's map
  };
  // A body's motion evaluated once per pass over its rows.
  struct Motion {
    Vec3 centre, velocity, omega, acceleration, alpha;
    Matrix33 R;
  };
  Motion motionOf(size_t body) const;
  // Each body's resultant (with gravity's m g) and moment about its centre of the forces -r on its rows, summed
  // over the ranks.
  void gatherForces(const Vector& r);
  // The bodies' rows of u (displacement), v and a (each optional) where the bodies put them.
  void place(Vector* u, Vector* v, Vector* a) const;

  std::vector<RigidBody> bodies_;
  std::vector<Row> rows_;
  // Every rigid node's DOFs (global id), on every rank: its body, component and body-frame
  // coordinates, for contact (describe).
  struct DofOfBody {
    int body, component;
    Vec3 xi;
  };
  std::unordered_map<GO, DofOfBody> dofsOfBodies_;
  std::vector<Vec3> force_, torque_;
  std::vector<Vec3> startCentre_;  // each body's centre at the start (gravity's work)
  Vec3 gravity_{};
  RCP<const Comm> comm_;
  RCP<const Vector> lumpedMass_;
  std::string inputFile_;
  std::vector<std::string> keys_, keyValues_;  // each body's 'Model/Blocks/<name>/Rigid' (or coupling's Type), for messages
  MassProperties blockProperties(const Model& model, int block, const std::vector<int>& elements,
                                 const std::vector<std::pair<Vec3, double>>& points) const;
  MassProperties pointProperties(const std::vector<int>& nodes, const Mesh& mesh,
                                 const std::vector<std::pair<Vec3, double>>& points) const;
  void addRows(const Model& model, int body, const std::vector<int>& nodes);
};

// Rigid blocks or kinematic couplings: bodies that move some nodes rigidly.
bool hasRigidBodies(const Model& model);

// The rigid blocks of the model refused by an analysis that cannot run them, naming the first.
void refuseRigidBlocks(const Model& model, const std::string& analysisPath, const std::string& what);

}  // namespace choc
