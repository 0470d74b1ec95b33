#include "contact/ContactParameters.hpp"

#include "contact/MortarSegments.hpp"
#include "core/DidYouMean.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "input/Vector3.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

const char* contactMethodName(ContactMethodKind m) {
  switch (m) {
    case ContactMethodKind::Lagrange: return "Lagrange";
    case ContactMethodKind::Penalty: return "Penalty";
    case ContactMethodKind::Continuous: return "Continuous";
    default: return "None";
  }
}

namespace {

// The enforcement method, its coefficients and its active-set tolerances.
void declareMethodParameters(ParameterList& ct) {
  declareChoice(ct, "Method", "None", {"None", "Lagrange", "Penalty", "Continuous"},
                "Lagrange: multipliers with an active set (CONTRAINTE); Penalty: E_N per slave "
                "node (PENALISATION); Continuous: augmented Lagrangian with pressure unknowns "
                "(CONTINUE)");
  declareDouble(ct, "Penalty Stiffness", 1e10, "E_N [N/m] per slave node (Penalty)", Range::positive());
  declareDouble(ct, "Augmentation Coefficient", 1e10,
                "c [N/m] of the augmented pressure lambda - c g (Continuous)", Range::positive());
  declareDouble(ct, "Gap Tolerance", 1e-12,
                "penetration [m] above which an inactive node enters the active set; with "
                "Penalty also the opening [m] above which an active node leaves it",
                Range::nonNegative());
  declareInt(ct, "Maximum Active Set Iterations", 20,
             "passes of Newton per step while the active set changes (each change of status "
             "starts one)", Range::atLeast(1));
  declareChoice(ct, "Status Update", "auto", {"auto", "each correction", "converged solve"},
                "when the contact status is re-evaluated in an implicit step: 'auto' 'each "
                "correction', or 'converged solve' when a block is plastic (J2, Johnson-Cook: the "
                "points' changes between elastic and plastic response and the status changes do "
                "not settle together); 'each correction' "
                "after every Newton correction (semi-smooth Newton: friction and active set "
                "converge together, about 3 corrections per step on the oblique sphere); "
                "'converged solve' only once Newton has converged with the status frozen (a "
                "fixed point of converged solves: each change costs a whole Newton solve). Both "
                "end on a state the Newton tests accept with the status it implies; their paths "
                "differ only where a pass takes more than one correction (friction, shock links, "
                "inexact linear solves)");
  declareDouble(ct, "Tangential Stiffness", 0.0,
                "k_t [N/m] per slave node of the pairs with friction: the stick spring (a sticking "
                "node's elastic slip is F_t / k_t); 0: the stiffness of the stiffest node, the "
                "largest mean of a node's diagonal entries of K over its components (the trace of "
                "its diagonal block over the dimension: the same in any frame)", Range::nonNegative());
}

// The obstacle in place of a pair's master side set.
void declareObstacleParameters(ParameterList& pr) {
  ParameterList& ob = declareSublist(pr, "Obstacle",
                                     "a rigid obstacle given by its geometry, in place of a master "
                                     "side set (every slave node is paired with it)");
  declareChoice(ob, "Shape", "none", {"none", "plane", "sphere", "cylinder"},
                "none: no obstacle; plane (body on the side 'Normal' points to), sphere or "
                "cylinder (body outside)");
  declareString(ob, "Point", "0 0 0",
                "'x y z' [m]: a point of the plane, the sphere's centre, a point of the "
                "cylinder's axis (at t = 0)");
  declareString(ob, "Normal", "0 0 1", "'x y z': the plane's normal, towards the body");
  declareString(ob, "Axis", "0 0 1", "'x y z': the cylinder's axis");
  declareDouble(ob, "Radius", 0.0, "sphere or cylinder radius [m]", Range::nonNegative());
  declareString(ob, "Velocity", "0 0 0", "'x y z' [m/s]: prescribed translation of the obstacle");
}

// A contact pair: its surfaces (or node sets, or obstacle), friction and search.
void declarePairParameters(ParameterList& ct) {
  ParameterList& pr = declareNamedSublists(
      ct, "Pairs",
      "contact pairs, by name (the name starts the pair's result columns: 1 to 32 letters, "
      "digits, '_', '-', '.')",
      NamedAs::OutputName);
  declareString(pr, "Master Side Set", "",
                "faces of solids (QUAD4, QUAD8, TRI3, TRI6) or edges of planar elements (LINE2, "
                "LINE3), outward normal; or give an 'Obstacle' instead");
  declareString(pr, "Slave Side Set", "", "faces whose nodes are the slave nodes");
  declareString(pr, "Slave Node Set", "",
                "instead of a slave side set, against an 'Obstacle' only: nodes without faces "
                "(beam structures, point masses), each a spring of 'Penalty Stiffness' or a "
                "multiplier; their pressure is not defined (0 in the output)");
  declareString(pr, "Master Node Set", "",
                "node to node (the plane of a shock link, for beam structures): each node of "
                "'Slave Node Set' with the nearest of these, gap = n . (x_slave - x_master) - "
                "'Node Offset', n = 'Node Normal'");
  declareString(pr, "Node Normal", "0 0 0", "'x y z': n of a node-to-node pair (normalised)");
  declareDouble(pr, "Node Offset", 0.0, "gap offset of a node-to-node pair [m] (DIST_1 + DIST_2)");
  declareDouble(pr, "Friction Coefficient", 0.0,
                "Coulomb mu of the pair: the tangential force stays within mu times the normal "
                "force, stick or slip decided in each Newton iteration (implicit schemes; 0: no "
                "friction)", Range::nonNegative());
  declareDouble(pr, "Search Distance", 1e-3,
                "largest |gap| of a pairing with a master side set [m]; also the reach of the "
                "search in the current configuration", Range::positive());
  declareChoice(pr, "Search", "current", {"current", "reference"},
                "with a master side set: current: every slave node is paired again before each "
                "step with the closest point of the master surface in the current configuration "
                "(mortar: the overlaps integrated again; curved surfaces, non-matching meshes, "
                "large sliding); reference: paired once at t = 0 (small sliding of aligned "
                "faces: the SDNL111 decks)");
  declareChoice(pr, "Discretization", "node to face", {"node to face", "mortar"},
                "with a master side set: node to face: each slave node against the closest point "
                "of the master surface; mortar: segment to segment with dual Lagrange "
                "multipliers (Wohlmuth): each slave node's gap and force are its dual shape "
                "function's averages over the master faces it overlaps, which passes the contact "
                "patch test on non-matching meshes; linear slave faces (TRI3, QUAD4, LINE2)");
  declareObstacleParameters(pr);
}

void declareContactMassParameter(ParameterList& p) {
  declareChoice(p, "Contact Mass", "auto", {"auto", "standard", "redistributed", "normal", "velocity update"},
                "standard: the blocks' mass matrices as they are; redistributed: the nodes of the "
                "contact pairs' master and slave side sets carry no mass, each element touching "
                "them has its mass moved onto its other nodes (element mass kept in every "
                "direction; Khenous, Laborde, Renard 2008): no chatter of the contact nodes and no "
                "energy created by it with any contact method, the contact surfaces' displacements "
                "found statically each step, their velocities reported as displacement "
                "differences; auto: with the implicit schemes, the velocity update when every block's "
                "mass is lumped, otherwise redistributed, whatever the contact method (standard when "
                "an element has every node on a contact surface), standard with central "
                "differences; normal (implicit schemes): as redistributed, but only along "
                "the contact surfaces' normals (their nodes keep their inertia along the surface: the "
                "element mass moved along the normal onto the nearest nodes off the surface); velocity "
                "update (implicit schemes): the standard mass, and "
                "after each step the velocity of the contact nodes projected with the lumped mass so "
                "that no active constraint approaches (Laursen and Love 2002; the kinetic energy it "
                "takes is counted in energy:dissipated)");
}

}  // namespace

void declareContactParameters(Teuchos::ParameterList& p) {
  ParameterList& ct = declareSublist(p, "Contact", "unilateral contact between side sets");
  declareMethodParameters(ct);
  declarePairParameters(ct);
  declareContactMassParameter(p);
}

namespace {

RigidObstacle readObstacle(const ParameterList& ob, const std::string& file, const std::string& path) {
  RigidObstacle o;
  const std::string shape = ob.get<std::string>("Shape");
  o.shape = shape == "plane"    ? RigidObstacle::Shape::Plane
            : shape == "sphere" ? RigidObstacle::Shape::Sphere
                                : RigidObstacle::Shape::Cylinder;
  o.point = parseVector3(ob.get<std::string>("Point"), file, path + "/Point");
  o.velocity = parseVector3(ob.get<std::string>("Velocity"), file, path + "/Velocity");
  const char* dirKey = o.shape == RigidObstacle::Shape::Cylinder ? "Axis" : "Normal";
  o.direction = parseVector3(ob.get<std::string>(dirKey), file, path + "/" + dirKey);
  o.radius = ob.get<double>("Radius");
  try {
    return validatedObstacle(o);
  } catch (const std::invalid_argument& e) {
    const bool radius = o.shape != RigidObstacle::Shape::Plane && !(o.radius > 0);
    throwInput(file, path + "/" + (radius ? "Radius" : dirKey),
               radius ? format("%g", o.radius) : ob.get<std::string>(dirKey), e.what(),
               radius ? "give the radius [m]" : "give a non-zero direction 'x y z'");
  }
}

PairDefinition readPair(const ParameterList& pl, const std::string& name, const std::string& file,
                        const std::string& path) {
  PairDefinition d{name, pl.get<std::string>("Master Side Set"), pl.get<std::string>("Slave Side Set"),
                   pl.get<double>("Search Distance")};
  d.slaveNodeSet = pl.get<std::string>("Slave Node Set");
  d.friction = pl.get<double>("Friction Coefficient");
  d.masterNodeSet = pl.get<std::string>("Master Node Set");
  const ParameterList& ob = pl.sublist("Obstacle");
  d.hasObstacle = ob.get<std::string>("Shape") != "none";
  d.mortar = pl.get<std::string>("Discretization") == "mortar";
  if (d.mortar && (d.hasObstacle || d.masterSideSet.empty()))
    throwInput(file, path + "/Discretization", "mortar",
               "mortar pairs a slave side set with a master side set, not with an obstacle or a node set",
               "give a 'Master Side Set', or leave 'Discretization' = node to face");
  if (!d.masterNodeSet.empty()) {  // node to node
    if (d.slaveNodeSet.empty() || !d.slaveSideSet.empty() || !d.masterSideSet.empty() || d.hasObstacle)
      throwInput(file, path + "/Master Node Set", d.masterNodeSet,
                 "a node-to-node pair takes a 'Slave Node Set' and nothing else",
                 "give 'Slave Node Set', 'Node Normal' and 'Node Offset' only");
    const std::string n = pl.get<std::string>("Node Normal");
    d.nodeNormal = parseVector3(n, file, path + "/Node Normal");
    const double len = norm(d.nodeNormal);
    if (!(len > 0))
      throwInput(file, path + "/Node Normal", n, "the normal of a node-to-node pair is zero",
                 "give the direction 'x y z' from the master node to the slave node");
    for (double& x : d.nodeNormal) x /= len;
    d.nodeOffset = pl.get<double>("Node Offset");
    return d;
  }
  if (d.slaveSideSet.empty() == d.slaveNodeSet.empty())
    throwInput(file, path + "/Slave Side Set", d.slaveSideSet,
               d.slaveSideSet.empty() ? "the pair has no slave surface"
                                      : "the pair also has a 'Slave Node Set'",
               "give either 'Slave Side Set' or (against an 'Obstacle') 'Slave Node Set'");
  if (!d.slaveNodeSet.empty() && !d.hasObstacle)
    throwInput(file, path + "/Slave Node Set", d.slaveNodeSet,
               "a slave node set has no faces to pair with a master side set",
               "give an 'Obstacle', or a 'Slave Side Set'");
  if (d.hasObstacle && !d.masterSideSet.empty())
    throwInput(file, path + "/Master Side Set", d.masterSideSet, "the pair also has an 'Obstacle'",
               "give either a master side set or an obstacle");
  if (!d.hasObstacle && d.masterSideSet.empty())
    throwInput(file, path, "", "the pair has neither a 'Master Side Set' nor an 'Obstacle'",
               "name the master side set, or give 'Obstacle/Shape'");
  if (!d.hasObstacle && d.masterSideSet == d.slaveSideSet)
    throwInput(file, path + "/Master Side Set", d.masterSideSet,
               "master and slave are the same surface", "pair two different side sets");
  if (d.hasObstacle) d.obstacle = readObstacle(ob, file, path + "/Obstacle");
  d.followMotion = !d.hasObstacle && pl.get<std::string>("Search") == "current";
  return d;
}

}  // namespace

ContactSettings readContactSettings(const Teuchos::ParameterList& p, const std::string& file,
                                    const std::string& path) {
  ContactSettings s;
  s.path = path;
  const ParameterList& ct = p.sublist("Contact");
  const std::string method = ct.get<std::string>("Method");
  s.method = method == "Lagrange"     ? ContactMethodKind::Lagrange
             : method == "Penalty"    ? ContactMethodKind::Penalty
             : method == "Continuous" ? ContactMethodKind::Continuous
                                      : ContactMethodKind::None;
  s.penaltyStiffness = ct.get<double>("Penalty Stiffness");
  s.augmentation = ct.get<double>("Augmentation Coefficient");
  s.gapTolerance = ct.get<double>("Gap Tolerance");
  s.maxActiveSetIterations = ct.get<int>("Maximum Active Set Iterations");
  s.statusUpdate = ct.get<std::string>("Status Update");
  s.tangentialStiffness = ct.get<double>("Tangential Stiffness");
  const std::string mass = p.get<std::string>("Contact Mass");
  s.massIsAutomatic = mass == "auto";
  s.redistributeMass = mass == "redistributed" || (s.massIsAutomatic && s.enabled());
  s.velocityUpdate = mass == "velocity update";
  s.normalMass = mass == "normal";
  if (s.enabled()) {
    const ParameterList& pairs = ct.sublist("Pairs");
    if (pairs.numParams() == 0)
      throwInput(file, path + "/Contact/Pairs", "", "contact method '" + s.methodName() + "' needs a pair",
                 "add a sublist with 'Master Side Set' and 'Slave Side Set'");
    for (auto it = pairs.begin(); it != pairs.end(); ++it)
      s.pairs.push_back(readPair(pairs.sublist(pairs.name(it)), pairs.name(it), file,
                                 path + "/Contact/Pairs/" + pairs.name(it)));
  }
  if ((s.redistributeMass || s.velocityUpdate || s.normalMass) && !s.massIsAutomatic && !s.enabled())
    throwInput(file, path + "/Contact Mass", mass, "there are no contact surfaces",
               "set 'Contact/Method' and 'Contact/Pairs', or use 'standard'");
  return s;
}

namespace {

std::unique_ptr<ContactMethod> makeContactMethod(const ContactSettings& s) {
  if (s.method == ContactMethodKind::Lagrange) return makeLagrangeContact(s.gapTolerance);
  if (s.method == ContactMethodKind::Penalty) return makePenaltyContact(s.penaltyStiffness, s.gapTolerance);
  return makeAugmentedLagrangianContact(s.augmentation, s.gapTolerance);
}

void requireSideSet(const Mesh& mesh, const std::string& name, const std::string& file,
                    const std::string& parameter) {
  if (mesh.findSideSet(name)) return;
  const auto names = mesh.sideSetNames();
  throwInput(file, parameter, name, "no side set of that name in the mesh",
             didYouMean(name, names) + "side sets: " + joinNames(names));
}

// Mortar's dual basis is defined on linear slave faces only.
void requireMortarFaces(const Mesh& mesh, const std::string& slave, const std::string& file,
                        const std::string& parameter) {
  std::vector<Face> faces;
  try {
    faces = facesOf(mesh, slave);
  } catch (const std::invalid_argument&) {
    return;  // the pairing reports it
  }
  for (const Face& f : faces)
    if (!mortarSlaveFace(f))
      throwInput(file, parameter, "mortar",
                 "slave side set '" + slave + "' has " + (f.edgeNodes ? std::string("LINE3") : topologyName(f.shape)) +
                     " faces: mortar takes TRI3, QUAD4 and LINE2 slave faces",
                 "make a surface of linear faces the slave, or use 'node to face'");
}

}  // namespace

std::unique_ptr<ContactManager> makeContactManager(const ContactSettings& s, const Mesh& mesh,
                                                   const DofMap& dofs, RCP<const Map> map,
                                                   const std::string& file, bool axisymmetric) {
  if (!s.enabled()) return nullptr;
  std::vector<PairDefinition> pairs = s.pairs;
  for (auto& p : pairs) p.axisymmetric = axisymmetric;
  for (const auto& pair : s.pairs) {
    const std::string pp = s.path + "/Contact/Pairs/" + pair.name;
    if (!pair.hasObstacle && pair.masterNodeSet.empty())
      requireSideSet(mesh, pair.masterSideSet, file, pp + "/Master Side Set");
    if (!pair.slaveNodeSet.empty()) {
      for (const auto& [set, key] : {std::make_pair(pair.slaveNodeSet, "Slave Node Set"),
                                     std::make_pair(pair.masterNodeSet, "Master Node Set")})
        if (!set.empty() && !mesh.findNodeSet(set))
          throwInput(file, pp + "/" + key, set, "no node set of that name in the mesh",
                     "node sets: " + joinNames(mesh.nodeSetNames()));
    } else {
      requireSideSet(mesh, pair.slaveSideSet, file, pp + "/Slave Side Set");
      if (pair.mortar) requireMortarFaces(mesh, pair.slaveSideSet, file, pp + "/Discretization");
    }
  }
  try {
    return std::make_unique<ContactManager>(mesh, dofs, map, pairs, makeContactMethod(s));
  } catch (const PairingError& e) {
    const PairDefinition& pair = s.pairs[e.pair];
    const std::string pp = s.path + "/Contact/Pairs/" + pair.name;
    if (pair.hasObstacle)
      throwInput(file, pp + "/Obstacle", shapeName(pair.obstacle.shape), e.what(),
                 "move the obstacle or the slave side set");
    if (!pair.masterNodeSet.empty())
      throwInput(file, pp + "/Master Node Set", pair.masterNodeSet, e.what(),
                 "give node sets whose nodes face each other one to one");
    throwInput(file, pp + "/Search Distance", format("%g", pair.searchDistance), e.what(),
               "check the side set names, or raise 'Search Distance' above the initial gaps");
  }
}

}  // namespace choc
