#include "physics/InitialConditions.hpp"

#include <array>

#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "core/Vec3.hpp"
#include "fem/Components.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Vector3.hpp"

namespace choc {

namespace {

const char* kRigid = "Rigid Velocity";

// The entry's value, required unless the field is a rigid velocity (which takes none).
void requireFor(const ParameterList& c, const std::string& key, bool rigid, const std::string& file,
                const std::string& path) {
  const bool given = !c.getEntry(key).isDefault();
  if (rigid && given)
    throwInput(file, path + "/" + key, Teuchos::toString(c.getEntry(key).getAny(false)),
               "is not used with Field = 'Rigid Velocity'",
               "remove it (the velocity is Translation + Angular Velocity x (x - Centre))");
  if (!rigid && !given)
    throwInput(file, path + "/" + key, "", "is required with Field = '" + c.get<std::string>("Field") + "'",
               "add it (Components e.g. 'DX', Value a number)");
}

// Field = Velocity or Displacement: Value on the node set's Components.
void setComponents(const ParameterList& c, const Model& model, const NodeSet& ns, const std::string& path,
                   Vector& target) {
  std::vector<int> comps;
  try {
    comps = parseComponents(c.get<std::string>("Components"));
  } catch (const std::invalid_argument& e) {
    throwInput(model.inputFile(), path + "/Components", c.get<std::string>("Components"), e.what());
  }
  const double value = c.get<double>("Value");
  for (int n : ns.nodes) {
    if (!model.dofs().ownsNode(n)) continue;
    for (int comp : comps) {
      const long long d = model.dof(n, comp);
      if (d >= 0) target.replaceGlobalValue(GO(d), value);
    }
  }
}

// The part of a rigid velocity a 2D model cannot carry: an error naming it.
void checkPlanar(const std::array<double, 3>& V, const std::array<double, 3>& w, Kinematics k,
                 const std::string& file, const std::string& path, const ParameterList& c) {
  if (k == Kinematics::PlaneStrain && V[2] != 0.0)
    throwInput(file, path + "/Translation", c.get<std::string>("Translation"),
               "has a z component in a plane-strain model", "give 'vx vy 0'");
  if (k == Kinematics::PlaneStrain && (w[0] != 0.0 || w[1] != 0.0))
    throwInput(file, path + "/Angular Velocity", c.get<std::string>("Angular Velocity"),
               "turns out of the plane of a plane-strain model", "give '0 0 wz'");
  if (k == Kinematics::Axisymmetric && V[0] != 0.0)
    throwInput(file, path + "/Translation", c.get<std::string>("Translation"),
               "moves an axisymmetric model radially (x is the radius: not a rigid motion)", "give '0 vy 0'");
  if (k == Kinematics::Axisymmetric && (w[0] != 0.0 || w[1] != 0.0 || w[2] != 0.0))
    throwInput(file, path + "/Angular Velocity", c.get<std::string>("Angular Velocity"),
               "is not zero in an axisymmetric model (a spin about the axis has no unknown; any other "
               "rotation is not axisymmetric)", "give '0 0 0'");
}

// Field = Rigid Velocity: v = V + omega x (x - x0) on the translations, omega on the rotations.
void setRigidVelocity(const ParameterList& c, const Model& model, const NodeSet& ns, const std::string& path,
                      Vector& target) {
  const std::string& file = model.inputFile();
  const auto V = parseVector3(c.get<std::string>("Translation"), file, path + "/Translation");
  const auto w = parseVector3(c.get<std::string>("Angular Velocity"), file, path + "/Angular Velocity");
  const auto x0 = parseVector3(c.get<std::string>("Centre"), file, path + "/Centre");
  checkPlanar(V, w, model.kinematics(), file, path, c);
  for (int n : ns.nodes) {
    if (!model.dofs().ownsNode(n)) continue;
    const Vec3 wr = cross(w, model.mesh().coords[n] - x0);
    const double v[6] = {V[0] + wr[0], V[1] + wr[1], V[2] + wr[2], w[0], w[1], w[2]};
    for (int comp = 0; comp < kNumComponents; ++comp) {
      const long long d = model.dof(n, comp);
      if (d >= 0) target.replaceGlobalValue(GO(d), v[comp]);
    }
  }
}

}  // namespace

void declareInitialConditions(Teuchos::ParameterList& p) {
  ParameterList& ic = declareNamedSublists(
      p, "Initial Conditions", "initial fields, by name (unset components start at zero)");
  declareRequiredString(ic, "Node Set", "node set receiving the value");
  declareChoice(ic, "Field", "Velocity", {"Velocity", "Displacement", kRigid},
                "which initial field: 'Velocity' or 'Displacement' sets Components to Value; 'Rigid "
                "Velocity' the velocity of a rigid motion, v = Translation + Angular Velocity x (x - "
                "Centre) on the translations, Angular Velocity on the rotations (beams)");
  declareString(ic, "Components", "",
                "components set, e.g. 'DX' (velocity too: 'DX' = VX); required with Field = Velocity "
                "or Displacement, refused with Rigid Velocity");
  declareDouble(ic, "Value", 0.0,
                "value [m/s or m]; required with Field = Velocity or Displacement, refused with Rigid "
                "Velocity");
  declareString(ic, "Translation", "0 0 0", "Rigid Velocity: V, the velocity of the point Centre [m/s], 'vx vy vz'");
  declareString(ic, "Angular Velocity", "0 0 0",
                "Rigid Velocity: omega [rad/s], 'wx wy wz' (plane strain: '0 0 wz'; axisymmetric: "
                "'0 0 0', with Translation '0 vy 0')");
  declareString(ic, "Centre", "0 0 0", "Rigid Velocity: x0, the point the rotation is about [m], 'x y z'");
}

InitialFields buildInitialFields(const Teuchos::ParameterList& p, const Model& model,
                                 const std::string& analysisPath) {
  InitialFields f;
  f.displacement = rcp(new Vector(model.map()));
  f.velocity = rcp(new Vector(model.map()));
  const ParameterList& ic = p.sublist("Initial Conditions");
  for (auto it = ic.begin(); it != ic.end(); ++it) {
    const std::string path = analysisPath + "/Initial Conditions/" + ic.name(it);
    const ParameterList& c = ic.sublist(ic.name(it));
    const NodeSet& ns = model.nodeSet(c.get<std::string>("Node Set"), path + "/Node Set");
    const std::string field = c.get<std::string>("Field");
    const bool rigid = field == kRigid;
    for (const char* key : {"Components", "Value"}) requireFor(c, key, rigid, model.inputFile(), path);
    if (rigid)
      setRigidVelocity(c, model, ns, path, *f.velocity);
    else
      setComponents(c, model, ns, path, field == "Velocity" ? *f.velocity : *f.displacement);
  }
  return f;
}

}  // namespace choc
