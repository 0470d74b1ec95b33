#include "physics/RigidBodies.hpp"

#include <algorithm>
#include <set>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "fem/Components.hpp"
#include "fem/DenseMatrix.hpp"
#include "fem/ElementKernel.hpp"
#include "fem/ShapeFunctions.hpp"
#include "physics/Model.hpp"
#include "restart/StateArchive.hpp"
#include "rigid/BlockMassProperties.hpp"

namespace choc {

namespace {

Vec3 sum(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

std::string rigidKey(const Model& model, int block) { return "Model/Blocks/" + model.mesh().blocks[size_t(block)].name + "/Rigid"; }

// The nodes of a block's elements.
std::set<int> blockNodes(const ElementBlock& blk) { return std::set<int>(blk.connectivity.begin(), blk.connectivity.end()); }

// The key naming each body in messages: a rigid block's 'Rigid', a kinematic coupling's 'Type'.
struct BodyKey {
  std::string path, value;
};

std::vector<BodyKey> bodyKeys(const Model& model) {
  std::vector<BodyKey> keys;
  for (int b : model.rigidBlocks()) keys.push_back({rigidKey(model, b), "true"});
  for (const ModelCoupling& c : model.couplings())
    if (c.kinematic) keys.push_back({"Model/Couplings/" + c.name + "/Type", "kinematic"});
  return keys;
}

// Each body's nodes: the rigid blocks' (in order), then the kinematic couplings'.
std::vector<std::vector<int>> bodyNodes(const Model& model) {
  std::vector<std::vector<int>> nodes;
  for (int b : model.rigidBlocks()) {
    const std::set<int> n = blockNodes(model.mesh().blocks[size_t(b)]);
    nodes.emplace_back(n.begin(), n.end());
  }
  for (const ModelCoupling& c : model.couplings())
    if (c.kinematic) nodes.push_back(c.nodes);
  return nodes;
}

// Which body moves each mesh node (-1: none). Two bodies share no node: they would be one.
std::vector<int> bodyOfNodes(const Model& model, const std::vector<std::vector<int>>& nodes,
                             const std::vector<BodyKey>& keys) {
  std::vector<int> body(size_t(model.mesh().numNodes()), -1);
  for (size_t k = 0; k < nodes.size(); ++k)
    for (int n : nodes[k]) {
      if (body[size_t(n)] >= 0 && body[size_t(n)] != int(k))
        throwInput(model.inputFile(), keys[k].path, keys[k].value,
                   "its node " + std::to_string(n + 1) + " is also a node of the body of " +
                       keys[size_t(body[size_t(n)])].path + " (two bodies cannot share a node)",
                   "make the two one rigid block, or keep their nodes apart");
      body[size_t(n)] = int(k);
    }
  return body;
}

// Per body, the lumped mass that the elements of deformable blocks give its nodes (the nodes a
// rigid block shares with them move with the body, and so does that mass), as point masses at
// the nodes: each of `elements` (this rank's share) summed once.
std::vector<std::vector<std::pair<Vec3, double>>> sharedNodeMasses(const Model& model, const std::vector<int>& body,
                                                                   const std::vector<int>& elements,
                                                                   const std::vector<BodyKey>& keys) {
  const Mesh& mesh = model.mesh();
  std::vector<std::vector<std::pair<Vec3, double>>> out(keys.size());
  DenseMatrix Me;
  std::vector<Point3> x;
  for (int ge : elements) {
    const auto [b, e] = mesh.locateElement(ge);
    const ElementBlock& blk = mesh.blocks[size_t(b)];
    const ElementKernel* kernel = model.elementKernel(b);
    if (!kernel || std::count(model.rigidBlocks().begin(), model.rigidBlocks().end(), b)) continue;
    const int* conn = &blk.connectivity[size_t(e) * size_t(blk.nodesPerElement)];
    const int* tied = std::find_if(conn, conn + blk.nodesPerElement, [&](int n) { return body[size_t(n)] >= 0; });
    if (tied == conn + blk.nodesPerElement) continue;
    x.clear();
    for (int a = 0; a < blk.nodesPerElement; ++a) x.push_back(mesh.coords[size_t(conn[a])]);
    const int nc = int(kernel->components().size());
    if (nc > 3)
      throwInput(model.inputFile(), keys[size_t(body[size_t(*tied)])].path, keys[size_t(body[size_t(*tied)])].value,
                 "it shares nodes with the beams of block '" + blk.name + "', whose rotations a rigid block does not hold so far",
                 "mesh the beams apart and join them otherwise, or make the part deformable");
    kernel->mass(x, MassKind::Lumped, Me);
    for (int a = 0; a < blk.nodesPerElement; ++a)
      if (body[size_t(conn[a])] >= 0) out[size_t(body[size_t(conn[a])])].push_back({x[size_t(a)], Me(a * nc, a * nc)});
  }
  return out;
}

// In a 2D model a body moves in its plane: its nodes have no z rows, and its forces and lever arms
// (z = 0) give it no z force and a moment about z only, about a principal axis of a planar body
// (no product of inertia with z), so it keeps V_z = 0 and w along z by itself. An axisymmetric
// body (masses per full ring) can only slide along the axis y: its radial translation and its
// rotation are held (the radial forces of its rings cancel by symmetry).
RigidHold planarHold(const Model& model, RigidHold hold, const BodyKey& key) {
  if (model.kinematics() != Kinematics::Axisymmetric) return hold;
  if (hold.translation[0] && hold.velocity[0] != 0.0)
    throwInput(model.inputFile(), key.path, key.value,
               "a body of an axisymmetric model moves along its axis only: its radial speed is 0",
               "hold DY only, or give 'Held Velocity' with x = 0");
  hold.translation[0] = true;
  hold.velocity[0] = 0.0;
  hold.rotation = true;
  return hold;
}

}  // namespace

bool hasRigidBodies(const Model& model) {
  const auto& c = model.couplings();
  return !model.rigidBlocks().empty() || std::any_of(c.begin(), c.end(), [](const ModelCoupling& k) { return k.kinematic; });
}

void refuseRigidBlocks(const Model& model, const std::string& analysisPath, const std::string& what) {
  if (!hasRigidBodies(model)) return;
  const BodyKey key = bodyKeys(model).front();
  const std::string bodies = key.value == "kinematic" ? "kinematic couplings" : "rigid blocks";
  throwInput(model.inputFile(), key.path, key.value,
             bodies + " run in explicit transients only so far (issue 74), and " + analysisPath + " is " + what,
             "use a 'Transient' with 'Scheme' = 'central differences', or mesh the part as a deformable block");
}

// A rigid block's mass properties: its elements and the point masses of its shared nodes.
MassProperties RigidBodies::blockProperties(const Model& model, int block, const std::vector<int>& elements,
                                            const std::vector<std::pair<Vec3, double>>& points) const {
  const Mesh& mesh = model.mesh();
  SolidShape shape{};
  if (!findSolidTopology(mesh.blocks[size_t(block)].topology, shape))
    throwInput(model.inputFile(), rigidKey(model, block), "true",
               "its elements are " + mesh.blocks[size_t(block)].topology + ": rigid blocks are solids so far",
               "mesh the part with solid elements");
  return blockMassProperties(mesh, {block}, {model.materialOfBlock(block).density}, model.kinematics(), elements,
                             *comm_, points);
}

// A kinematic coupling's: its nodes' lumped masses, summed over the ranks.
MassProperties RigidBodies::pointProperties(const std::vector<int>& nodes, const Mesh& mesh,
                                            const std::vector<std::pair<Vec3, double>>& points) const {
  MassPropertiesSum sum(mesh.coords[size_t(nodes.front())]);
  for (const auto& [x, m] : points) sum.addPoint(x, m);
  const std::vector<double> mine = sum.sums();
  std::vector<double> all(mine.size());
  Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, int(mine.size()), mine.data(), all.data());
  sum.setSums(all);
  return sum.properties();
}

// The body's DOFs (every component of its nodes, free: its motion is held on the body) and this
// rank's rows of them.
void RigidBodies::addRows(const Model& model, int body, const std::vector<int>& nodes) {
  const Mesh& mesh = model.mesh();
  const RCP<const Map> map = model.map();
  const int components = int(spatialComponents(mesh.dimension).size());  // 2D: x and y
  for (int n : nodes)
    for (int c = 0; c < components; ++c) {
      const long long g = model.dof(n, c);
      if (g < 0)
        throwInput(model.inputFile(), keys_[size_t(body)], keyValues_[size_t(body)],
                   "its node " + std::to_string(n + 1) + " has component " + std::string(1, "XYZ"[c]) +
                       " fixed or inactive (a rigid body's motion is held on the body, 'Held', not on its nodes)",
                   "remove the node from the Dirichlet sets and Active Components");
      const Vec3 xi = bodies_.back().bodyCoordinates(mesh.coords[size_t(n)]);
      dofsOfBodies_[GO(g)] = {body, c, xi};
      const LO row = map->getLocalElement(GO(g));
      if (row != Teuchos::OrdinalTraits<LO>::invalid()) rows_.push_back({body, mesh.coords[size_t(n)], xi, c, row});
    }
}

RigidBodies::RigidBodies(const Model& model, const Vector& lumpedMass)
    : comm_(model.comm()), lumpedMass_(rcp(new Vector(lumpedMass, Teuchos::Copy))), inputFile_(model.inputFile()) {
  const Mesh& mesh = model.mesh();
  // Each element summed once: on the rank that owns its first node (localElements() holds every
  // element touching an owned node).
  std::vector<int> elements;
  for (int ge : model.localElements()) {
    const auto [b, e] = mesh.locateElement(ge);
    const ElementBlock& blk = mesh.blocks[size_t(b)];
    if (model.dofs().ownerOfNode(blk.connectivity[size_t(e) * size_t(blk.nodesPerElement)]) == comm_->getRank())
      elements.push_back(ge);
  }
  const std::vector<BodyKey> keys = bodyKeys(model);
  const std::vector<std::vector<int>> nodes = bodyNodes(model);
  const auto shared = sharedNodeMasses(model, bodyOfNodes(model, nodes, keys), elements, keys);
  std::vector<const ModelCoupling*> kinematic;
  for (const ModelCoupling& c : model.couplings())
    if (c.kinematic) kinematic.push_back(&c);
  const size_t blocks = model.rigidBlocks().size();
  for (size_t k = 0; k < keys.size(); ++k) {
    keys_.push_back(keys[k].path);
    keyValues_.push_back(keys[k].value);
    try {  // no mass (a zero density), or no inertia about an axis: the same on every rank
      const bool block = k < blocks;
      const MassProperties p = block ? blockProperties(model, model.rigidBlocks()[k], elements, shared[k])
                                     : pointProperties(nodes[k], mesh, shared[k]);
      bodies_.emplace_back(block ? mesh.blocks[size_t(model.rigidBlocks()[k])].name : kinematic[k - blocks]->name, p);
      bodies_.back().setHold(planarHold(model, block ? model.rigidHold(k) : kinematic[k - blocks]->hold, keys[k]));
    } catch (const std::invalid_argument& e) {
      throwInput(model.inputFile(), keys[k].path, keys[k].value, e.what(),
                 "a rigid body needs mass and inertia about every axis: check its elements or nodes");
    }
    addRows(model, int(k), nodes[k]);
  }
  force_.assign(bodies_.size(), Vec3{});
  torque_.assign(bodies_.size(), Vec3{});
  for (const RigidBody& b : bodies_) startCentre_.push_back(b.centre());
}

void RigidBodies::zeroRows(Vector& x) const {
  auto d = x.getDataNonConst();
  for (const Row& r : rows_) d[r.row] = 0.0;
}

double RigidBodies::kineticEnergy() const {
  double e = 0.0;
  for (const RigidBody& b : bodies_) e += b.kineticEnergy();
  return e;
}

// The holds' work, and gravity's m g . (c - c0) (exact: a constant force).
double RigidBodies::externalWork() const {
  double w = 0.0;
  for (size_t b = 0; b < bodies_.size(); ++b)
    w += bodies_[b].holdWork() + bodies_[b].mass() * dot(gravity_, bodies_[b].centre() - startCentre_[b]);
  return w;
}

RigidBodies::Motion RigidBodies::motionOf(size_t b) const {
  const RigidBody& body = bodies_[b];
  Motion m;
  m.centre = body.centre();
  m.velocity = body.centreVelocity();
  m.omega = body.angularVelocity();
  m.R = body.attitude();
  m.acceleration = {force_[b][0] / body.mass(), force_[b][1] / body.mass(), force_[b][2] / body.mass()};
  m.alpha = body.angularAcceleration(torque_[b]);
  return m;
}

// Each row's force -r_i and its moment r x f about the centre (r = R xi: the body's attitude
// taken once per body).
void RigidBodies::gatherForces(const Vector& r) {
  const auto d = r.getData();
  std::vector<double> local(6 * bodies_.size(), 0.0), global(local.size());
  std::vector<Matrix33> R;
  for (const RigidBody& b : bodies_) R.push_back(b.attitude());
  for (const Row& row : rows_) {
    Vec3 f{};
    f[size_t(row.component)] = -d[row.row];
    const Vec3 m = cross(R[size_t(row.body)] * row.xi, f);
    local[size_t(6 * row.body + row.component)] += f[size_t(row.component)];
    for (int k = 0; k < 3; ++k) local[size_t(6 * row.body + 3 + k)] += m[size_t(k)];
  }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  for (size_t b = 0; b < bodies_.size(); ++b)
    for (int k = 0; k < 3; ++k) {
      force_[b][size_t(k)] = global[6 * b + size_t(k)] + bodies_[b].mass() * gravity_[size_t(k)];
      torque_[b][size_t(k)] = global[6 * b + 3 + size_t(k)];
    }
}

// x = c + r, r = R xi; u = x - X, v = V + w x r, a = A + alpha x r + w x (w x r): each body's
// motion evaluated once.
void RigidBodies::place(Vector* u, Vector* v, Vector* a) const {
  Teuchos::ArrayRCP<double> du = u ? u->getDataNonConst() : Teuchos::ArrayRCP<double>();
  Teuchos::ArrayRCP<double> dv = v ? v->getDataNonConst() : Teuchos::ArrayRCP<double>();
  Teuchos::ArrayRCP<double> da = a ? a->getDataNonConst() : Teuchos::ArrayRCP<double>();
  std::vector<Motion> motion;
  for (size_t b = 0; b < bodies_.size(); ++b) motion.push_back(motionOf(b));
  for (const Row& row : rows_) {
    const Motion& m = motion[size_t(row.body)];
    const size_t c = size_t(row.component);
    const Vec3 r = m.R * row.xi;
    if (u) du[row.row] = m.centre[c] + r[c] - row.X[c];
    if (v) dv[row.row] = m.velocity[c] + cross(m.omega, r)[c];
    if (a) da[row.row] = m.acceleration[c] + cross(m.alpha, r)[c] + cross(m.omega, cross(m.omega, r))[c];
  }
}

// The nodes' initial velocities fitted by a rigid motion in the lumped mass's norm: V of the
// nodes' lumped centre c_l = P / m_l, w = I_l^-1 L_l (the nodes' momentum and angular momentum
// about c_l, I_l their lumped inertia there: MassPropertiesSum of the nodes as point masses);
// exact when the nodes move rigidly. The body then moves at V + w x (c - c_l) and w. Initial
// displacements of a body's nodes are refused.
void RigidBodies::start(const Vector& u, Vector& v) {
  const auto du = u.getData(), dv = v.getData(), m = lumpedMass_->getData();
  const size_t nb = bodies_.size();
  std::vector<MassPropertiesSum> nodes;
  for (const RigidBody& b : bodies_) nodes.emplace_back(b.centre());  // about a point of the body
  // per body: sum m v (3), sum m (X - c) x v (3), c the reference point of `nodes`
  std::vector<double> local(6 * nb, 0.0), global(local.size());
  std::vector<int> displaced(nb, 0), anyDisplaced(nb, 0);
  for (const Row& row : rows_) {
    double* s = &local[6 * size_t(row.body)];
    const double mi = m[row.row], vi = dv[row.row];
    if (du[row.row] != 0.0) displaced[size_t(row.body)] = 1;
    Vec3 e{};
    e[size_t(row.component)] = vi;
    const Vec3 xv = cross(row.X - bodies_[size_t(row.body)].centre(), e);
    s[row.component] += mi * vi;
    for (int k = 0; k < 3; ++k) s[3 + k] += mi * xv[size_t(k)];
    if (row.component == 0) nodes[size_t(row.body)].addPoint(row.X, mi);  // a node once, with its X row
  }
  if (nb > 0) Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, int(nb), displaced.data(), anyDisplaced.data());
  for (size_t b = 0; b < nb; ++b)
    if (anyDisplaced[b])
      throwInput(inputFile_, keys_[b], keyValues_[b],
                 "its nodes are given an initial displacement (not available for a rigid body so far, issue 74)",
                 "remove the displacement of its nodes from the Initial Conditions");
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  for (size_t b = 0; b < nb; ++b) {
    std::vector<double> sums = nodes[b].sums(), all(sums.size());
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, int(sums.size()), sums.data(), all.data());
    nodes[b].setSums(all);
    const MassProperties lumped = nodes[b].properties();
    RigidBody& body = bodies_[b];
    const Vec3 c = body.centre(), cl = lumped.centre;
    const Vec3 P = {global[6 * b], global[6 * b + 1], global[6 * b + 2]};
    const Vec3 Vl = {P[0] / lumped.mass, P[1] / lumped.mass, P[2] / lumped.mass};
    // about c_l: sum m (X - c_l) x v = sum m (X - c) x v - (c_l - c) x P
    const Vec3 L = Vec3{global[6 * b + 3], global[6 * b + 4], global[6 * b + 5]} - cross(cl - c, P);
    const Vec3 Lp = transpose(lumped.axes) * L;
    const Vec3 w = lumped.axes * Vec3{Lp[0] / lumped.moments[0], Lp[1] / lumped.moments[1], Lp[2] / lumped.moments[2]};
    body.setMotion(sum(Vl, cross(w, c - cl)), w);
    if (body.hold().any()) body.setHold(body.hold());  // the held components from the start
  }
  place(nullptr, &v, nullptr);
}

void RigidBodies::accelerate(const Vector& r, Vector& a) {
  gatherForces(r);
  place(nullptr, nullptr, &a);
}

// A copy of each body kicked by the forces -r over factor h (the rest of this sub-step's kick
// and the next one's) and drifted over h: where its rows will be without contact.
void RigidBodies::predict(double h, double factor, const Vector& r, Vector& uStar) {
  gatherForces(r);
  std::vector<RigidBody> next = bodies_;
  for (size_t b = 0; b < next.size(); ++b) {
    next[b].kick(force_[b], torque_[b], factor * h);
    next[b].drift(h);
  }
  auto d = uStar.getDataNonConst();
  for (const Row& row : rows_) {
    const RigidBody& b = next[size_t(row.body)];
    d[row.row] = b.centre()[size_t(row.component)] + (b.attitude() * row.xi)[size_t(row.component)] -
                 row.X[size_t(row.component)];
  }
}

// Per DOF its body's lever arm R xi now; per body 1/m and R diag(1/I) R^T.
RigidContactBodies RigidBodies::describe(const std::vector<GO>& dofs) const {
  RigidContactBodies out;
  out.dofs.resize(dofs.size());
  for (size_t k = 0; k < dofs.size(); ++k) {
    const auto it = dofsOfBodies_.find(dofs[k]);
    if (it == dofsOfBodies_.end()) continue;
    out.dofs[k] = {it->second.body, it->second.component, bodies_[size_t(it->second.body)].attitude() * it->second.xi};
  }
  for (const RigidBody& b : bodies_) {
    const RigidHold& hold = b.hold();
    Vec3 w{};
    for (int c = 0; c < 3; ++c) w[size_t(c)] = hold.translation[size_t(c)] ? 0.0 : 1.0 / b.mass();
    out.inverseMass.push_back(w);
    const Matrix33& R = b.attitude();
    const Vec3& I = b.principalMoments();
    std::array<double, 9> J{};
    for (int i = 0; i < 3 && !hold.rotation; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k) J[size_t(3 * i + j)] += R[size_t(3 * i + k)] * R[size_t(3 * j + k)] / I[size_t(k)];
    out.inverseInertia.push_back(J);
  }
  return out;
}

void RigidBodies::drift(double h, Vector& u, Vector& vHalf) {
  for (size_t b = 0; b < bodies_.size(); ++b) {
    bodies_[b].kick(force_[b], torque_[b], 0.5 * h);
    bodies_[b].drift(h);
  }
  place(&u, &vHalf, nullptr);
}

void RigidBodies::kick(double h, const Vector& r, Vector& v, Vector& a) {
  gatherForces(r);
  for (size_t b = 0; b < bodies_.size(); ++b) bodies_[b].kick(force_[b], torque_[b], 0.5 * h);
  place(nullptr, &v, &a);
}

std::vector<std::string> RigidBodies::historyColumns() const {
  static const char* const names[] = {"X",  "Y",  "Z",  "VX", "VY", "VZ", "RX", "RY", "RZ", "WX", "WY", "WZ",
                                      "PX", "PY", "PZ", "LX", "LY", "LZ", "kinetic", "FX", "FY", "FZ",
                                      "MX", "MY", "MZ"};
  static const char* const held[] = {"reactionX", "reactionY", "reactionZ", "reactionMX", "reactionMY", "reactionMZ"};
  std::vector<std::string> c;
  for (const RigidBody& b : bodies_) {
    for (const char* n : names) c.push_back(b.name() + ":" + n);
    if (b.hold().any())
      for (const char* n : held) c.push_back(b.name() + ":" + n);
  }
  return c;
}

std::vector<double> RigidBodies::historyValues() const {
  std::vector<double> v;
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const RigidBody& body = bodies_[b];
    for (const Vec3& x : {body.centre(), body.centreVelocity(), body.rotationVector(), body.angularVelocity(),
                          body.momentum(), body.angularMomentum()})
      v.insert(v.end(), x.begin(), x.end());
    v.push_back(body.kineticEnergy());
    v.insert(v.end(), force_[b].begin(), force_[b].end());
    v.insert(v.end(), torque_[b].begin(), torque_[b].end());
    if (!body.hold().any()) continue;
    v.insert(v.end(), body.reactionForce().begin(), body.reactionForce().end());
    v.insert(v.end(), body.reactionMoment().begin(), body.reactionMoment().end());
  }
  return v;
}

void RigidBodies::archive(StateArchive& a) const {
  for (size_t b = 0; b < bodies_.size(); ++b) {
    std::vector<double> s = bodies_[b].state();
    s.insert(s.end(), force_[b].begin(), force_[b].end());
    s.insert(s.end(), torque_[b].begin(), torque_[b].end());
    a.putVector("rigid/" + bodies_[b].name(), s);
  }
}

void RigidBodies::restore(const StateArchive& a) {
  for (size_t b = 0; b < bodies_.size(); ++b) {
    const std::vector<double> s = a.getVector<double>("rigid/" + bodies_[b].name(), 31);
    bodies_[b].restore(std::vector<double>(s.begin(), s.begin() + 25));
    for (int k = 0; k < 3; ++k) force_[b][size_t(k)] = s[size_t(25 + k)], torque_[b][size_t(k)] = s[size_t(28 + k)];
  }
}

}  // namespace choc
