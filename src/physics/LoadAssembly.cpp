// The loads of a transient from its input (Analyses/<name>/Nodal Forces, Pressures and Coupling
// Loads), each a load group of Loads.hpp or a state load.
#include "physics/LoadAssembly.hpp"

#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "fem/Components.hpp"
#include "input/Vector3.hpp"
#include "physics/CouplingLoad.hpp"

namespace choc {

namespace {

// The follower pressure `name` (Pressures/<name>, Follower = true) on its faces: finite-strain
// blocks under every face, or an input error.
std::shared_ptr<const FollowerPressure> followerPressure(Model& model, const Teuchos::ParameterList& q,
                                                         std::vector<Face> faces, const PressureField& field,
                                                         const std::string& inputFile, const std::string& key) {
  const std::string name = key.substr(key.rfind('/') + 1);
  const std::string side = q.get<std::string>("Side Set");
  if (model.firstFiniteStrainBlock().empty())
    throwInput(inputFile, key + "/Follower", "true",
               "a follower pressure makes the model nonlinear and needs a block with Strain = finite",
               "set Strain = finite on the loaded block, or Follower = false (a dead load on the reference faces)");
  for (int e : model.mesh().findSideSet(side)->elements) {  // facesOf found the set
    const int b = model.mesh().locateElement(e).first;
    const auto& kernel = model.finiteStrainKernels()[size_t(b)];
    if (!kernel || !kernel->finiteKinematics())
      throwInput(inputFile, key + "/Side Set", side,
                 "has faces of block '" + model.mesh().blocks[size_t(b)].name +
                     "', whose Strain is small: a follower pressure loads finite-strain blocks",
                 "set Strain = finite on that block, or Follower = false");
  }
  const int components = static_cast<int>(spatialComponents(model.mesh().dimension).size());
  return std::make_shared<FollowerPressure>(name, std::move(faces), field, q.get<double>("Ramp Time"),
                                            model.kinematics() == Kinematics::Axisymmetric, model.dofs(),
                                            components, *model.stiffness());
}

// The load on a coupling (Coupling Loads/<name>): a state load on finite-strain models (the
// forces follow the nodes), else the same forces on the reference positions (a dead load).
void addCouplingLoad(Model& model, Loads& loads, const Teuchos::ParameterList& q, const std::string& inputFile,
                     const std::string& key) {
  const std::string name = key.substr(key.rfind('/') + 1), which = q.get<std::string>("Coupling");
  const ModelCoupling* c = nullptr;
  for (const ModelCoupling& k : model.couplings())
    if (k.name == which) c = &k;
  if (!c) throwInput(inputFile, key + "/Coupling", which, "no entry of Model/Couplings of that name",
                     "name a coupling of Model/Couplings, or add one there");
  const Vec3 F = parseVector3(q.get<std::string>("Force"), inputFile, key + "/Force");
  const Vec3 M = parseVector3(q.get<std::string>("Moment"), inputFile, key + "/Moment");
  std::vector<Point3> X;
  for (int n : c->nodes) X.push_back(model.mesh().coords[size_t(n)]);
  std::vector<double> f;
  try {
    couplingForce(X, F, M, f, nullptr);
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile, key + "/Moment", q.get<std::string>("Moment"), std::string("coupling '") + which + "': " + e.what(),
               "couple nodes that span a face, or give no moment");
  }
  if (c->kinematic && (M[0] != 0.0 || M[1] != 0.0 || M[2] != 0.0) && model.firstFiniteStrainBlock().empty())
    throwInput(inputFile, key + "/Moment", q.get<std::string>("Moment"),
               "a moment on a kinematic coupling of a small-strain model is not available so far (its forces would "
               "stay where the turning nodes were)",
               "set Strain = finite on a block, or give no moment");
  if (!model.firstFiniteStrainBlock().empty()) {
    loads.addFollower(std::make_shared<CouplingLoad>(name, c->nodes, model.mesh(), F, M, q.get<double>("Ramp Time"),
                                                     model.dofs(), 3, *model.stiffness()));
    return;
  }
  auto force = rcp(new Vector(model.map()));
  for (size_t i = 0; i < c->nodes.size(); ++i)
    if (model.dofs().ownsNode(c->nodes[i]))
      for (int d = 0; d < 3; ++d) force->sumIntoGlobalValue(GO(model.dof(c->nodes[i], d)), f[3 * i + size_t(d)]);
  loads.add({name, force, q.get<double>("Ramp Time")});
}

// Gravity on the deformable blocks: M g (M the model's mass: the consistent body force when it is
// consistent), without the rows of rigid blocks' nodes (each body takes m g at its centre:
// RigidBodies::setGravity). A 2D model takes g in its plane.
void addGravity(Model& model, Loads& loads, const Vec3& g, const std::string& inputFile, const std::string& key,
                const std::string& text) {
  if (g[0] == 0.0 && g[1] == 0.0 && g[2] == 0.0) return;
  const Mesh& mesh = model.mesh();
  auto field = rcp(new Vector(model.map()));
  const int components = int(spatialComponents(mesh.dimension).size());
  if (components < 3 && g[2] != 0.0)
    throwInput(inputFile, key, text, "a 2D model moves in the x-y plane", "give gravity with z = 0");
  for (int n = 0; n < mesh.numNodes(); ++n) {
    if (!model.dofs().ownsNode(n)) continue;
    for (int c = 0; c < components; ++c)
      if (model.dof(n, c) >= 0) field->replaceGlobalValue(GO(model.dof(n, c)), g[size_t(c)]);
  }
  auto force = rcp(new Vector(model.map()));
  model.mass()->apply(*field, *force);
  auto f = force->getDataNonConst();
  std::vector<int> bodies;  // the nodes rigid bodies move: rigid blocks' and kinematic couplings'
  for (int b : model.rigidBlocks())
    bodies.insert(bodies.end(), mesh.blocks[size_t(b)].connectivity.begin(), mesh.blocks[size_t(b)].connectivity.end());
  for (const ModelCoupling& c : model.couplings())
    if (c.kinematic) bodies.insert(bodies.end(), c.nodes.begin(), c.nodes.end());
  for (int n : bodies)
    for (int c = 0; c < components; ++c) {
      const long long d = model.dof(n, c);
      const LO row = d < 0 ? LO(-1) : model.map()->getLocalElement(GO(d));
      if (d >= 0 && row != Teuchos::OrdinalTraits<LO>::invalid()) f[row] = 0.0;
    }
  loads.add({"gravity", force, 0.0});
}

}  // namespace

// Nodal forces and pressures, each a load group (null when there are none).
std::shared_ptr<const Loads> assembleLoads(Model& model, const Teuchos::ParameterList& analysis,
                                           const std::string& inputFile, const std::string& analysisPath) {
  const auto path = [&](const std::string& key) { return analysisPath + "/" + key; };
  auto loads = std::make_shared<Loads>();
  const Teuchos::ParameterList& nf = analysis.sublist("Nodal Forces");
  for (auto it = nf.begin(); it != nf.end(); ++it) {
    const Teuchos::ParameterList& f = nf.sublist(nf.name(it));
    const NodeSet& ns = model.nodeSet(f.get<std::string>("Node Set"), path("Nodal Forces/" + nf.name(it) + "/Node Set"));
    const int comp = componentFromName(f.get<std::string>("Component"));
    auto force = rcp(new Vector(model.map()));
    for (int n : ns.nodes) {
      const long long d = model.dof(n, comp);
      if (d >= 0 && model.dofs().ownsNode(n)) force->sumIntoGlobalValue(GO(d), f.get<double>("Value"));
    }
    loads->add({nf.name(it), force, f.get<double>("Ramp Time")});
  }
  const Teuchos::ParameterList& pr = analysis.sublist("Pressures");
  for (auto it = pr.begin(); it != pr.end(); ++it) {
    const Teuchos::ParameterList& q = pr.sublist(pr.name(it));
    const std::string side = q.get<std::string>("Side Set");
    std::vector<Face> faces;
    try {
      faces = facesOf(model.mesh(), side);
    } catch (const std::invalid_argument& e) {
      throwInput(inputFile, path("Pressures/" + pr.name(it) + "/Side Set"), side, e.what());
    }
    const std::string key = path("Pressures/" + pr.name(it));
    PressureField field;
    field.value = q.get<double>("Value");
    field.gradient = parseVector3(q.get<std::string>("Gradient"), inputFile, key + "/Gradient");
    if (q.get<bool>("Follower")) {
      loads->addFollower(followerPressure(model, q, std::move(faces), field, inputFile, key));
      continue;
    }
    auto force = rcp(new Vector(model.map()));
    const auto nodal = pressureForces(faces, field, model.kinematics() == Kinematics::Axisymmetric);
    for (const auto& [n, fn] : nodal) {
      if (!model.dofs().ownsNode(n)) continue;
      for (int c = 0; c < 3; ++c) {
        const long long d = model.dof(n, c);
        if (d >= 0 && fn[c] != 0.0) force->sumIntoGlobalValue(GO(d), fn[c]);
      }
    }
    loads->add({pr.name(it), force, q.get<double>("Ramp Time")});
  }
  const std::string gravity = analysis.get<std::string>("Gravity");
  addGravity(model, *loads, parseVector3(gravity, inputFile, path("Gravity")), inputFile, path("Gravity"), gravity);
  const Teuchos::ParameterList& cl = analysis.sublist("Coupling Loads");
  for (auto it = cl.begin(); it != cl.end(); ++it)
    addCouplingLoad(model, *loads, cl.sublist(cl.name(it)), inputFile, path("Coupling Loads/" + cl.name(it)));
  if (loads->empty()) return nullptr;
  return loads;
}

}  // namespace choc
