#include "physics/Model.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <sstream>

#include "fem/Beam2Element.hpp"
#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "fem/NodePartition.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "core/Resources.hpp"
#include <chrono>
#include "fem/SolidElement.hpp"
#include "mesh/Topology.hpp"
#include "core/Errors.hpp"
#include "core/Memory.hpp"
#include "mesh/CoincidentNodes.hpp"
#include "physics/DegenerateElements.hpp"
#include "physics/RigidHoldInput.hpp"
#include "materials/MaterialLaw.hpp"
#include "input/Validation.hpp"
#include "input/Vector3.hpp"
#include "input/XmlInput.hpp"
#include "mesh/MeshFile.hpp"

namespace choc {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

BeamSection beamSection(const Teuchos::ParameterList& sec, const std::string& file,
                        const std::string& path) {
  BeamSection s;
  const double side = sec.get<double>("Square Side");
  if (side > 0) {
    s = squareSection(side);
  } else {
    s.area = sec.get<double>("Area");
    s.Iy = sec.get<double>("Iy");
    s.Iz = sec.get<double>("Iz");
    s.torsionConstant = sec.get<double>("Torsion Constant");
    for (const char* k : {"Area", "Iy", "Iz", "Torsion Constant"})
      if (!(sec.get<double>(k) > 0))
        throwInput(file, path + "/" + k, entryToString(sec.getEntry(k)),
                   "a beam block needs a positive value",
                   "set 'Square Side' or all of Area, Iy, Iz, Torsion Constant");
  }
  s.shearCoefficientY = s.shearCoefficientZ = sec.get<double>("Shear Coefficient");
  s.orientation = parseVector3(sec.get<std::string>("Orientation"), file, path + "/Orientation");
  return s;
}

}  // namespace

Model::Model(const Teuchos::ParameterList& input, const std::string& inputFile,
             RCP<const Comm> comm)
    : inputFile_(inputFile), comm_(std::move(comm)) {
  const std::string meshFile = readMesh(input.sublist("Mesh"));
  const Teuchos::ParameterList& model = input.sublist("Model");
  kinematics_ = kinematicsFromName(model.get<std::string>("Kinematics"));
  const std::vector<BlockPhysics> physics = blockPhysics(model);
  const auto checkStart = std::chrono::steady_clock::now();
  checkElementGeometry(physics, input.sublist("Mesh").get<std::string>("File"));
  logPhase(*comm_, "element geometry check", secondsSince(checkStart));
  std::vector<std::uint8_t> mask = freeComponents(model, physics);
  readSprings(model.sublist("Springs"));
  const auto partitionStart = std::chrono::steady_clock::now();
  buildDofMap(std::move(mask), model.get<std::string>("Partition"));
  logPhase(*comm_, "partition and DOF map (" + std::to_string(dofs_->numGlobal()) + " unknowns)",
           secondsSince(partitionStart));
  if (dofs_->numGlobal() == 0)
    throwInput(inputFile_, "Model/Active Components", model.get<std::string>("Active Components"),
               "the model has no unknowns", "check the active components and Dirichlet sets");
  try {
    assembler_ = std::make_unique<Assembler>(mesh_, *dofs_, physics, comm_);
  } catch (const std::invalid_argument& e) {
    throwInput(inputFile_, "Mesh/File", meshFile, e.what());
  }
  readCouplings(model.sublist("Couplings"));
}

// Reads 'Mesh/File' (relative to the input file); returns its path.
std::string Model::readMesh(const Teuchos::ParameterList& meshList) {
  const std::string given = meshList.get<std::string>("File");
  const std::string meshFile = resolveBeside(inputFile_, given);
  const auto readStart = std::chrono::steady_clock::now();
  try {
    mesh_ = readMeshFile(meshFile);
  } catch (const InputError& e) {
    throwInput(inputFile_, "Mesh/File", given, std::string("cannot use the mesh: ") + e.what());
  }
  logPhase(*comm_, "mesh read (" + std::to_string(mesh_.numNodes()) + " nodes, " +
                       std::to_string(mesh_.numElements()) + " elements)",
           secondsSince(readStart));
  checkDegenerateElements(mesh_, inputFile_, given);
  handleCoincidentNodes(meshList);
  return meshFile;
}

// Every mesh block needs an entry in Model/Blocks, every entry a mesh block; each block's
// material, mass and element kernel.
std::vector<BlockPhysics> Model::blockPhysics(const Teuchos::ParameterList& model) {
  const std::string& file = inputFile_;
  const Teuchos::ParameterList& mats = model.sublist("Materials");
  std::vector<std::string> matNames;
  for (auto it = mats.begin(); it != mats.end(); ++it) {
    matNames.push_back(mats.name(it));
    checkMaterialKeys(file, mats.name(it), mats.sublist(mats.name(it)));
  }
  const Teuchos::ParameterList& blocks = model.sublist("Blocks");
  const auto meshBlocks = mesh_.blockNames();
  for (auto it = blocks.begin(); it != blocks.end(); ++it)
    if (!mesh_.findBlock(blocks.name(it)))
      throwInput(file, "Model/Blocks/" + blocks.name(it), "", "no element block of that name in the mesh",
                 didYouMean(blocks.name(it), meshBlocks) + "blocks: " + joinNames(meshBlocks));
  std::vector<BlockPhysics> physics(mesh_.blocks.size());
  blockMaterial_.resize(mesh_.blocks.size());
  for (size_t b = 0; b < mesh_.blocks.size(); ++b) {
    const ElementBlock& blk = mesh_.blocks[b];
    const std::string path = "Model/Blocks/" + blk.name;
    if (!blocks.isSublist(blk.name))
      throwInput(file, "Model/Blocks", "", "mesh block '" + blk.name + "' has no entry",
                 "add <ParameterList name=\"" + blk.name + "\"> with its Material");
    const Teuchos::ParameterList& bp = blocks.sublist(blk.name);
    const std::string matName = bp.get<std::string>("Material");
    if (!mats.isSublist(matName))
      throwInput(file, path + "/Material", matName, "no material of that name",
                 didYouMean(matName, matNames) + "materials: " + joinNames(matNames));
    const Teuchos::ParameterList& mp = mats.sublist(matName);
    const ElasticConstants elastic = materialLaw(mp.get<std::string>("Model")).elasticConstants(mp);
    Material m;
    m.youngsModulus = elastic.youngsModulus;
    m.poissonsRatio = elastic.poissonsRatio;
    m.density = mp.get<double>("Density");
    blockMaterial_[b] = m;
    physics[b].mass = bp.get<std::string>("Mass") == "lumped" ? MassKind::Lumped : MassKind::Consistent;
    physics[b].kernel = blockKernel(blk, kinematics_, m, bp, file);
    physics[b].rigid = bp.get<bool>("Rigid");
    if (physics[b].rigid) physics[b].mass = MassKind::Lumped;  // its nodes' masses weigh their initial velocities
    // A rigid block has no strain: no element-by-element kernel (physics/RigidBodies.hpp).
    finite_.push_back(physics[b].rigid ? nullptr : strainKernel(blk, bp, matName, mp));
    const RigidHold hold = rigidHoldOf(bp, physics[b].rigid, file, path);
    if (physics[b].rigid) rigidBlocks_.push_back(int(b)), rigidHolds_.push_back(hold);
    physics[b].fullPattern = finite_.back() != nullptr;
    kernels_.push_back(physics[b].kernel);
  }
  return physics;
}

// The components that are unknowns: carried by an element, active, not fixed by a Dirichlet
// condition (one bit per component and node).
std::vector<std::uint8_t> Model::freeComponents(const Teuchos::ParameterList& model,
                                                const std::vector<BlockPhysics>& physics) const {
  std::vector<std::uint8_t> mask = Assembler::carriedComponents(mesh_, physics);
  const auto bits = [&](const std::string& path, const std::string& components) {
    std::uint8_t b = 0;
    try {
      for (int c : parseComponents(components)) b |= std::uint8_t(1u << c);
    } catch (const std::invalid_argument& e) {
      throwInput(inputFile_, path, components, e.what());
    }
    return b;
  };
  const std::uint8_t active = bits("Model/Active Components", model.get<std::string>("Active Components"));
  for (auto& m : mask) m &= active;
  const Teuchos::ParameterList& dir = model.sublist("Dirichlet");
  for (auto it = dir.begin(); it != dir.end(); ++it) {
    const std::string path = "Model/Dirichlet/" + dir.name(it);
    const Teuchos::ParameterList& d = dir.sublist(dir.name(it));
    const NodeSet& ns = nodeSet(d.get<std::string>("Node Set"), path + "/Node Set");
    const std::uint8_t fixed = bits(path + "/Components", d.get<std::string>("Components"));
    for (int n : ns.nodes) mask[n] &= std::uint8_t(~fixed);
  }
  return mask;
}

// Parts meshed apart whose nodes meet are not connected: say so once, or join them.
void Model::handleCoincidentNodes(const Teuchos::ParameterList& meshList) {
  const CoincidentNodes found = findCoincidentNodes(mesh_);
  if (found.duplicates() == 0) return;
  const auto [a, b] = found.pairs.front();
  const Point3& x = mesh_.coords[a];
  const std::string where = format("%d node(s) lie within %.3g m of a node of other elements they are "
                                   "not shared with (first: nodes %d and %d at (%.6g, %.6g, %.6g))",
                                   found.duplicates(), found.tolerance, a + 1, b + 1, x[0], x[1], x[2]);
  if (meshList.get<bool>("Merge Coincident Nodes")) {
    mergeCoincidentNodes(mesh_, found);
    log() << "mesh: " << where << ": merged ('Mesh/Merge Coincident Nodes')\n";
    return;
  }
  log() << "choc: warning: " << inputFile_ << ": mesh '" << meshList.get<std::string>("File") << "': "
        << where << "; the parts are not connected there: set 'Mesh/Merge Coincident Nodes' = true "
        << "if they are one body (contact surfaces that touch at the start are fine)\n";
}

// The element of a block: beams and HEX8 by their own kernels (3D), every other solid by the
// isoparametric library; a block that does not fit the kinematics is an input error.
std::shared_ptr<const ElementKernel> Model::blockKernel(const ElementBlock& blk, Kinematics kin,
                                                        const Material& m,
                                                        const Teuchos::ParameterList& bp,
                                                        const std::string& file) const {
  const std::string path = "Model/Blocks/" + blk.name;
  const Topology* topo = findTopology(blk.topology);
  const int dim = topo ? topo->dimension : 0;
  if ((kin == Kinematics::ThreeD) != (dim != 2))
    throwInput(file, "Model/Kinematics", toString(kin),
               "block '" + blk.name + "' has " + blk.topology + " elements" +
                   (dim == 2 ? " (a 2D mesh)" : ""),
               dim == 2 ? "set 'Kinematics' to 'plane strain' or 'axisymmetric'"
                        : "give a 2D mesh (TRI3, TRI6, QUAD4, QUAD8) or set 'Kinematics' to '3D'");
  try {
    if (blk.topology == "BEAM2") return makeBeam2(m, beamSection(bp.sublist("Section"), file, path + "/Section"));
    if (blk.topology == "HEX8") return makeHex8(m);
    return makeSolidElement(blk.topology, kin, m);
  } catch (const std::invalid_argument& e) {
    throwInput(file, blk.topology == "BEAM2" ? path + "/Section" : path, "", e.what());
  }
}

// Every element's Jacobian at its quadrature points, before anything is assembled: an
// inverted or degenerate element is named (block, element number in the file) in one line.
void Model::checkElementGeometry(const std::vector<BlockPhysics>& physics,
                                 const std::string& meshParameter) const {
  int first = 0;
  for (size_t b = 0; b < mesh_.blocks.size(); ++b) {
    const ElementBlock& blk = mesh_.blocks[b];
    if (!physics[b].kernel) continue;
    std::vector<Point3> x(blk.nodesPerElement);
    for (int e = 0; e < blk.numElements(); ++e) {
      for (int k = 0; k < blk.nodesPerElement; ++k) x[k] = mesh_.coords[blk.connectivity[size_t(e) * blk.nodesPerElement + k]];
      try {
        physics[b].kernel->checkGeometry(x);
      } catch (const std::invalid_argument& err) {
        throwInput(inputFile_, "Mesh/File", meshParameter,
                   "block '" + blk.name + "', element " + std::to_string(first + e + 1) + ": " + err.what());
      }
    }
    first += blk.numElements();
  }
}

// Model/Springs: a spring on every node of each set, its direction normalised.
void Model::readSprings(const Teuchos::ParameterList& springs) {
  for (auto it = springs.begin(); it != springs.end(); ++it) {
    const std::string path = "Model/Springs/" + springs.name(it);
    const Teuchos::ParameterList& s = springs.sublist(springs.name(it));
    const NodeSet& ns = nodeSet(s.get<std::string>("Node Set"), path + "/Node Set");
    const std::string text = s.get<std::string>("Direction");
    Point3 d = parseVector3(text, inputFile_, path + "/Direction");
    const double len = norm(d);
    if (!(len > 0))
      throwInput(inputFile_, path + "/Direction", text, "a spring's axis needs a non-zero direction",
                 "give 'x y z' with a non-zero component, e.g. '1 0 0'");
    if (kinematics_ != Kinematics::ThreeD && d[2] != 0.0)
      throwInput(inputFile_, path + "/Direction", text, "a 2D model moves in the x-y plane",
                 "give a direction with z = 0");
    for (double& c : d) c /= len;
    for (int n : ns.nodes) springs_.push_back({n, d, s.get<double>("Stiffness")});
  }
}

// Model/Couplings: each node set's nodes, every component of each an unknown (a load spread on a
// fixed component would go to the support); the stiffness' graph couples them.
void Model::readCouplings(const Teuchos::ParameterList& couplings) {
  std::vector<std::vector<int>> groups;
  const int components = int(spatialComponents(mesh_.dimension).size());
  for (auto it = couplings.begin(); it != couplings.end(); ++it) {
    const std::string path = "Model/Couplings/" + couplings.name(it);
    const Teuchos::ParameterList& c = couplings.sublist(couplings.name(it));
    const std::string set = c.get<std::string>("Node Set");
    const NodeSet& ns = nodeSet(set, path + "/Node Set");
    if (kinematics_ != Kinematics::ThreeD)
      throwInput(inputFile_, path + "/Type", c.get<std::string>("Type"), "couplings are 3D only so far (issue 74)",
                 "model the part in 3D, or load its nodes with Nodal Forces");
    if (ns.nodes.empty())
      throwInput(inputFile_, path + "/Node Set", set, "the node set is empty", "give a node set with the coupled nodes");
    for (int n : ns.nodes)
      for (int k = 0; k < components; ++k)
        if (dofs_->dof(n, k) < 0)
          throwInput(inputFile_, path + "/Node Set", set,
                     "its node " + std::to_string(n + 1) + " has component " + std::string(1, "XYZ"[k]) +
                         " fixed or inactive (the load spread on it would go to the support)",
                     "couple free nodes only: remove them from the Dirichlet sets, or from the coupling's set");
    const bool kinematic = c.get<std::string>("Type") == "kinematic";
    couplings_.push_back({couplings.name(it), ns.nodes, kinematic,
                          rigidHoldOf(c, kinematic, inputFile_, path, "the coupling is distributing")});
    if (!kinematic) groups.push_back(ns.nodes);  // its load stiffness couples them
  }
  assembler_->coupleNodes(std::move(groups));
}

// The DOF map on the ranks: Zoltan2 RCB parts (the default), or ranges of the mesh's
// numbering. The log gives the partition's quality.
void Model::buildDofMap(std::vector<std::uint8_t> mask, const std::string& method) {
  const int p = comm_->getSize();
  if (method == "numbering" || p == 1) {
    dofs_ = std::make_unique<DofMap>(std::move(mask), p, comm_->getRank());
    return;
  }
  const auto start = std::chrono::steady_clock::now();
  NodePartition part;
  try {
    part = partitionNodes(mesh_, mask, p);
  } catch (const std::exception& e) {
    rethrowIfOutOfMemory(describeFailure(e), "partition of the nodes");
    throw NumericalError(std::string("partition of the nodes: ") + e.what());
  }
  const PartitionQuality q = partitionQuality(mesh_, mask, part);
  std::string dofs;
  for (long long d : q.dofsPerPart) dofs += (dofs.empty() ? "" : ", ") + std::to_string(d);
  log() << format("partition: Zoltan2 RCB into %d parts in %.3f s: unknowns per rank %s (imbalance %.3f), "
                  "%lld nodes on elements shared by parts\n",
                  p, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
                  dofs.c_str(), q.imbalance, q.sharedNodes);
  dofs_ = std::make_unique<DofMap>(std::move(mask), part.order, part.rankBegin, comm_->getRank());
}

MPI_Comm Model::rawComm() const {
  auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(comm_);
  if (mpi.is_null()) return MPI_COMM_SELF;
  return (*mpi->getRawMpiComm())();
}

const NodeSet& Model::nodeSet(const std::string& name, const std::string& parameter) const {
  if (const NodeSet* ns = mesh_.findNodeSet(name)) return *ns;
  const auto names = mesh_.nodeSetNames();
  throwInput(inputFile_, parameter, name, "no node set of that name in the mesh",
             didYouMean(name, names) + "node sets: " + joinNames(names));
}

RCP<const CrsMatrix> Model::stiffness() {
  if (K_.is_null()) {
    const auto start = std::chrono::steady_clock::now();
    try {
      K_ = assembler_->stiffness(springs_);
    } catch (const std::invalid_argument& e) {
      throwInput(inputFile_, "Mesh/File", "", std::string("bad element: ") + e.what());
    }
    logPhase(*comm_, "stiffness assembly (" + std::to_string(K_->getGlobalNumEntries()) + " entries)",
             secondsSince(start));
  }
  return K_;
}

RCP<const CrsMatrix> Model::mass() {
  if (M_.is_null()) {
    const auto start = std::chrono::steady_clock::now();
    M_ = assembler_->mass();
    logPhase(*comm_, "mass assembly", secondsSince(start));
  }
  return M_;
}

RCP<const CrsMatrix> Model::mass(const std::vector<char>& massless) const {
  return assembler_->mass(massless);
}

RCP<const CrsMatrix> Model::mass(const std::vector<std::vector<Point3>>& directions) const {
  return assembler_->mass(directions);
}

}  // namespace choc
