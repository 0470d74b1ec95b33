#include "physics/Model.hpp"

#include <Teuchos_DefaultMpiComm.hpp>

#include <algorithm>
#include <sstream>

#include "fem/Beam2Element.hpp"
#include "fem/Components.hpp"
#include "fem/Hex8Element.hpp"
#include "core/Errors.hpp"
#include "input/Validation.hpp"
#include "input/Vector3.hpp"
#include "input/XmlInput.hpp"
#include "mesh/ExodusReader.hpp"

namespace choc {

namespace {

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
  const std::string& file = inputFile_;
  const std::string meshFile =
      resolveBeside(inputFile, input.sublist("Mesh").get<std::string>("File"));
  try {
    mesh_ = readExodusMesh(meshFile);
  } catch (const InputError& e) {
    throwInput(file, "Mesh/File", input.sublist("Mesh").get<std::string>("File"),
               std::string("cannot use the mesh: ") + e.what());
  }
  const Teuchos::ParameterList& model = input.sublist("Model");

  // Materials
  const Teuchos::ParameterList& mats = model.sublist("Materials");
  std::vector<std::string> matNames;
  for (auto it = mats.begin(); it != mats.end(); ++it) matNames.push_back(mats.name(it));

  // Blocks: every mesh block needs an entry, every entry a mesh block.
  const Teuchos::ParameterList& blocks = model.sublist("Blocks");
  const auto meshBlocks = mesh_.blockNames();
  for (auto it = blocks.begin(); it != blocks.end(); ++it) {
    const std::string& name = blocks.name(it);
    if (!mesh_.findBlock(name)) {
      throwInput(file, "Model/Blocks/" + name, "", "no element block of that name in the mesh",
                 didYouMean(name, meshBlocks) + "blocks: " +
                     joinNames(meshBlocks));
    }
  }
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
    if (!mats.isSublist(matName)) {
      throwInput(file, path + "/Material", matName, "no material of that name",
                 didYouMean(matName, matNames) + "materials: " +
                     joinNames(matNames));
    }
    const Teuchos::ParameterList& mp = mats.sublist(matName);
    Material m;
    m.youngsModulus = mp.get<double>("Young's Modulus");
    m.poissonsRatio = mp.get<double>("Poisson's Ratio");
    m.density = mp.get<double>("Density");
    blockMaterial_[b] = m;
    physics[b].mass = bp.get<std::string>("Mass") == "lumped" ? MassKind::Lumped : MassKind::Consistent;
    if (blk.topology == "BEAM2") {
      try {
        physics[b].kernel = makeBeam2(m, beamSection(bp.sublist("Section"), file, path + "/Section"));
      } catch (const std::invalid_argument& e) {
        throwInput(file, path + "/Section", "", e.what());
      }
    } else if (blk.topology == "HEX8") {
      physics[b].kernel = makeHex8(m);
    } else {
      throwInput(file, path, blk.topology, "element topology not supported", "use BEAM2 or HEX8");
    }
  }

  // Free components: carried by an element, active, not fixed by a Dirichlet condition.
  std::vector<std::uint8_t> mask = Assembler::carriedComponents(mesh_, physics);
  std::uint8_t active = 0;
  try {
    for (int c : parseComponents(model.get<std::string>("Active Components")))
      active |= std::uint8_t(1u << c);
  } catch (const std::invalid_argument& e) {
    throwInput(file, "Model/Active Components", model.get<std::string>("Active Components"),
               e.what());
  }
  for (auto& m : mask) m &= active;
  const Teuchos::ParameterList& dir = model.sublist("Dirichlet");
  for (auto it = dir.begin(); it != dir.end(); ++it) {
    const std::string path = "Model/Dirichlet/" + dir.name(it);
    const Teuchos::ParameterList& d = dir.sublist(dir.name(it));
    const NodeSet& ns = nodeSet(d.get<std::string>("Node Set"), path + "/Node Set");
    std::uint8_t fixed = 0;
    try {
      for (int c : parseComponents(d.get<std::string>("Components"))) fixed |= std::uint8_t(1u << c);
    } catch (const std::invalid_argument& e) {
      throwInput(file, path + "/Components", d.get<std::string>("Components"), e.what());
    }
    for (int n : ns.nodes) mask[n] &= std::uint8_t(~fixed);
  }
  dofs_ = std::make_unique<DofMap>(std::move(mask), comm_->getSize(), comm_->getRank());
  if (dofs_->numGlobal() == 0)
    throwInput(file, "Model/Active Components", model.get<std::string>("Active Components"),
               "the model has no unknowns", "check the active components and Dirichlet sets");
  try {
    assembler_ = std::make_unique<Assembler>(mesh_, *dofs_, physics, comm_);
  } catch (const std::invalid_argument& e) {
    throwInput(file, "Mesh/File", meshFile, e.what());
  }
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
    try {
      K_ = assembler_->stiffness();
    } catch (const std::invalid_argument& e) {
      throwInput(inputFile_, "Mesh/File", "", std::string("bad element: ") + e.what());
    }
  }
  return K_;
}

RCP<const CrsMatrix> Model::mass() {
  if (M_.is_null()) M_ = assembler_->mass();
  return M_;
}

RCP<const CrsMatrix> Model::mass(const std::vector<char>& massless) const {
  return assembler_->mass(massless);
}

}  // namespace choc
