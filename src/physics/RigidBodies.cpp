#include "physics/RigidBodies.hpp"

#include <set>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
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

// A rigid block's nodes are its body's alone: no element of another block shares one.
void checkNodesOwnedByTheBody(const Model& model, int block, const std::set<int>& nodes) {
  const Mesh& mesh = model.mesh();
  for (size_t b = 0; b < mesh.blocks.size(); ++b) {
    if (int(b) == block) continue;
    for (int n : mesh.blocks[b].connectivity)
      if (nodes.count(n))
        throwInput(model.inputFile(), rigidKey(model, block), "true",
                   "its node " + std::to_string(n + 1) + " is also a node of block '" + mesh.blocks[b].name +
                       "' (a rigid block shares no node with another block so far: issue 74's couplings will tie them)",
                   "mesh the parts apart and let contact join them, or declare both blocks rigid as one block");
  }
}

}  // namespace

void refuseRigidBlocks(const Model& model, const std::string& analysisPath, const std::string& what) {
  const std::vector<int> rigid = model.rigidBlocks();
  if (rigid.empty()) return;
  throwInput(model.inputFile(), rigidKey(model, rigid.front()), "true",
             "rigid blocks run in explicit transients only so far (issue 74), and " + analysisPath + " is " + what,
             "use a 'Transient' with 'Scheme' = 'central differences', or mesh the part as a deformable block");
}

RigidBodies::RigidBodies(const Model& model, const Vector& lumpedMass)
    : comm_(model.comm()), lumpedMass_(rcp(new Vector(lumpedMass, Teuchos::Copy))), inputFile_(model.inputFile()) {
  const Mesh& mesh = model.mesh();
  const RCP<const Map> map = model.map();
  // Each element summed once: on the rank that owns its first node (localElements() holds every
  // element touching an owned node).
  std::vector<int> elements;
  for (int ge : model.localElements()) {
    const auto [b, e] = mesh.locateElement(ge);
    const ElementBlock& blk = mesh.blocks[size_t(b)];
    if (model.dofs().ownerOfNode(blk.connectivity[size_t(e) * size_t(blk.nodesPerElement)]) == comm_->getRank())
      elements.push_back(ge);
  }
  for (int block : model.rigidBlocks()) {
    if (model.kinematics() != Kinematics::ThreeD)
      throwInput(model.inputFile(), rigidKey(model, block), "true", "rigid blocks are 3D only so far (issue 74)",
                 "model the part as a deformable block");
    SolidShape shape{};
    if (!findSolidTopology(mesh.blocks[size_t(block)].topology, shape))
      throwInput(model.inputFile(), rigidKey(model, block), "true",
                 "its elements are " + mesh.blocks[size_t(block)].topology + ": rigid blocks are solids so far",
                 "mesh the part with solid elements");
    const std::set<int> nodes = blockNodes(mesh.blocks[size_t(block)]);
    checkNodesOwnedByTheBody(model, block, nodes);
    const int body = int(bodies_.size());
    keys_.push_back(rigidKey(model, block));
    try {  // no mass (a zero density), or no inertia about an axis: the same on every rank
      const MassProperties p = blockMassProperties(mesh, {block}, {model.materialOfBlock(block).density},
                                                   model.kinematics(), elements, *comm_);
      bodies_.emplace_back(mesh.blocks[size_t(block)].name, p);
    } catch (const std::invalid_argument& e) {
      throwInput(model.inputFile(), rigidKey(model, block), "true", e.what(),
                 "a rigid body needs mass and inertia about every axis: check the block's elements");
    }
    for (int n : nodes)
      for (int c = 0; c < 3; ++c) {
        const long long g = model.dof(n, c);
        if (g < 0)
          throwInput(model.inputFile(), rigidKey(model, block), "true",
                     "its node " + std::to_string(n + 1) + " has component " + std::string(1, "XYZ"[c]) +
                         " fixed or inactive (a rigid body's motion is prescribed on the body, not its nodes: "
                         "not yet available, issue 74)",
                     "remove the node from the Dirichlet sets and Active Components");
        const LO row = map->getLocalElement(GO(g));
        if (row != Teuchos::OrdinalTraits<LO>::invalid()) rows_.push_back({body, mesh.coords[size_t(n)], c, row});
      }
  }
  force_.assign(bodies_.size(), Vec3{});
  torque_.assign(bodies_.size(), Vec3{});
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

void RigidBodies::gatherForces(const Vector& r) {
  const auto d = r.getData();
  std::vector<double> local(6 * bodies_.size(), 0.0), global(local.size());
  for (const Row& row : rows_) {
    Vec3 f{};
    f[size_t(row.component)] = -d[row.row];
    const Vec3 m = bodies_[size_t(row.body)].momentOf(row.X, f);
    local[size_t(6 * row.body + row.component)] += f[size_t(row.component)];
    for (int k = 0; k < 3; ++k) local[size_t(6 * row.body + 3 + k)] += m[size_t(k)];
  }
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  for (size_t b = 0; b < bodies_.size(); ++b)
    for (int k = 0; k < 3; ++k) force_[b][size_t(k)] = global[6 * b + size_t(k)], torque_[b][size_t(k)] = global[6 * b + 3 + size_t(k)];
}

void RigidBodies::place(Vector* u, Vector* v, Vector* a) const {
  Teuchos::ArrayRCP<double> du = u ? u->getDataNonConst() : Teuchos::ArrayRCP<double>();
  Teuchos::ArrayRCP<double> dv = v ? v->getDataNonConst() : Teuchos::ArrayRCP<double>();
  Teuchos::ArrayRCP<double> da = a ? a->getDataNonConst() : Teuchos::ArrayRCP<double>();
  for (const Row& r : rows_) {
    const RigidBody& b = bodies_[size_t(r.body)];
    const size_t c = size_t(r.component);
    if (u) du[r.row] = b.displacement(r.X)[c];
    if (v) dv[r.row] = b.velocity(r.X)[c];
    if (a) da[r.row] = b.acceleration(r.X, force_[size_t(r.body)], torque_[size_t(r.body)])[c];
  }
}

// The nodes' initial velocities fitted by a rigid motion in the lumped mass's norm: V of the
// nodes' lumped centre c_l = P / m_l, w = I_l^-1 L_l (the nodes' momentum and angular momentum
// about c_l, I_l their lumped inertia there); exact when the nodes move rigidly. The body then
// moves at V + w x (c - c_l) and w. Initial displacements of a body's nodes are refused.
void RigidBodies::start(const Vector& u, const Vector& r, Vector& v, Vector& a) {
  const auto du = u.getData(), dv = v.getData(), m = lumpedMass_->getData();
  const size_t nb = bodies_.size();
  // per body: m_l, sum m X (3), sum m v (3), sum m X x v (3), sum m X_i X_j (6): 16
  std::vector<double> local(16 * nb, 0.0), global(local.size());
  std::vector<int> displaced(nb, 0), anyDisplaced(nb, 0);
  for (const Row& row : rows_) {
    double* s = &local[16 * size_t(row.body)];
    const double mi = m[row.row], vi = dv[row.row];
    if (du[row.row] != 0.0) displaced[size_t(row.body)] = 1;
    const int c = row.component;
    s[4 + c] += mi * vi;
    Vec3 e{};
    e[size_t(c)] = vi;
    const Vec3 xv = cross(row.X, e);
    for (int k = 0; k < 3; ++k) s[7 + k] += mi * xv[size_t(k)];
    if (c != 0) continue;  // the node's mass and moments once, with its X row
    s[0] += mi;
    for (int k = 0; k < 3; ++k) s[1 + k] += mi * row.X[size_t(k)];
    const int pair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
    for (int p = 0; p < 6; ++p) s[10 + p] += mi * row.X[size_t(pair[p][0])] * row.X[size_t(pair[p][1])];
  }
  if (nb > 0) Teuchos::reduceAll(*comm_, Teuchos::REDUCE_MAX, int(nb), displaced.data(), anyDisplaced.data());
  for (size_t b = 0; b < nb; ++b)
    if (anyDisplaced[b])
      throwInput(inputFile_, keys_[b], "true",
                 "its nodes are given an initial displacement (not available for a rigid body so far, issue 74)",
                 "remove the displacement of its nodes from the Initial Conditions");
  if (!local.empty())
    Teuchos::reduceAll(*comm_, Teuchos::REDUCE_SUM, int(local.size()), local.data(), global.data());
  for (size_t b = 0; b < nb; ++b) {
    const double* s = &global[16 * b];
    const double ml = s[0];
    const Vec3 cl = {s[1] / ml, s[2] / ml, s[3] / ml}, P = {s[4], s[5], s[6]};
    const Vec3 Vl = {P[0] / ml, P[1] / ml, P[2] / ml};
    const Vec3 L = Vec3{s[7], s[8], s[9]} - cross(cl, P);  // about c_l: sum m (X - c_l) x v
    Matrix33 S{};  // sum m (X - c_l)(X - c_l)^T
    const int pair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
    for (int p = 0; p < 6; ++p) {
      const int i = pair[p][0], j = pair[p][1];
      S[size_t(3 * i + j)] = S[size_t(3 * j + i)] = s[10 + p] - ml * cl[size_t(i)] * cl[size_t(j)];
    }
    const double tr = S[0] + S[4] + S[8];
    Matrix33 I{};
    for (int k = 0; k < 9; ++k) I[size_t(k)] = (k % 4 == 0 ? tr : 0.0) - S[size_t(k)];
    const Eigen33 e = eigenOfSymmetric33(I);
    const Vec3 Lp = transpose(e.vectors) * L;
    const Vec3 w = e.vectors * Vec3{Lp[0] / e.values[0], Lp[1] / e.values[1], Lp[2] / e.values[2]};
    RigidBody& body = bodies_[b];
    const Vec3 V = sum(Vl, cross(w, body.centre() - cl));
    body.setMotion(V, w);
  }
  gatherForces(r);
  place(nullptr, &v, &a);
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
  std::vector<std::string> c;
  for (const RigidBody& b : bodies_)
    for (const char* n : names) c.push_back(b.name() + ":" + n);
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
    const std::vector<double> s = a.getVector<double>("rigid/" + bodies_[b].name(), 24);
    bodies_[b].restore(std::vector<double>(s.begin(), s.begin() + 18));
    for (int k = 0; k < 3; ++k) force_[b][size_t(k)] = s[size_t(18 + k)], torque_[b][size_t(k)] = s[size_t(21 + k)];
  }
}

}  // namespace choc
