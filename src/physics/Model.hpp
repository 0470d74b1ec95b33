// The discrete model of one input: mesh, element physics per block, the DOF map (only the
// components the scene needs are unknowns) and the assembled stiffness and mass.
#pragma once
#include <mpi.h>

#include <memory>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "fem/Assembler.hpp"
#include "fem/DofMap.hpp"
#include "fem/FiniteStrainSolid.hpp"
#include "fem/Kinematics.hpp"
#include "fem/Material.hpp"
#include "core/TpetraTypes.hpp"
#include "mesh/Mesh.hpp"
#include "rigid/RigidBody.hpp"

namespace choc {

// A coupling of a node set (Model/Couplings/<name>): its nodes, each with every component free.
struct ModelCoupling {
  std::string name;
  std::vector<int> nodes;
  bool kinematic = false;  // Type = kinematic: the nodes move as one rigid body
  RigidHold hold;          // a kinematic coupling's Held motion
};

class MaterialLaw;

class Model {
 public:
  // `input` is the validated top-level list; `inputFile` is used for messages and to
  // resolve the mesh path.
  Model(const Teuchos::ParameterList& input, const std::string& inputFile, RCP<const Comm> comm);
  // The assembler holds references into the model: neither copied nor moved.
  Model(const Model&) = delete;
  Model& operator=(const Model&) = delete;

  const Mesh& mesh() const { return mesh_; }
  const DofMap& dofs() const { return *dofs_; }
  RCP<const Map> map() const { return assembler_->map(); }
  RCP<const Comm> comm() const { return comm_; }
  // The raw MPI communicator of comm() (MPI_COMM_WORLD unless the model was built on another).
  MPI_Comm rawComm() const;
  const std::string& inputFile() const { return inputFile_; }
  RCP<const CrsMatrix> stiffness();  // assembled once, cached
  RCP<const CrsMatrix> mass();
  // Per mesh block: the element-by-element kernel of a block whose 'Strain' is 'finite' (total
  // Lagrangian) or whose material is plastic (small or finite strain), else null. stiffness() is every block's small-strain stiffness all the same: the tangent at u = 0.
  const std::vector<std::shared_ptr<const FiniteStrainSolid>>& finiteStrainKernels() const { return finite_; }
  // The small-strain kernel of a block (its mass, its stiffness at u = 0); null without unknowns.
  const ElementKernel* elementKernel(int block) const { return kernels_[size_t(block)].get(); }
  // Some block is computed element by element: 'Strain' = 'finite', or a plastic material.
  bool finiteStrain() const;
  // The first block with 'Strain' = 'finite' ("" when none), for messages.
  std::string firstFiniteStrainBlock() const;
  // The first block with a plastic material ("" when none), for messages.
  std::string firstPlasticBlock() const;
  bool hasOnePointBlocks() const;
  // The small-strain blocks' stiffness and the springs, on stiffness()'s graph (the entries
  // finite-strain blocks alone give are zero).
  RCP<const CrsMatrix> smallStrainStiffness();
  // Elements (global indices) computed on this rank, in global order (Assembler).
  const std::vector<int>& localElements() const { return assembler_->localElements(); }
  // The mass with the flagged nodes (one entry per mesh node) massless and their elements' mass
  // redistributed onto the other nodes (Assembler::mass(massless)); not cached. Throws
  // std::invalid_argument when an element has every node flagged.
  RCP<const CrsMatrix> mass(const std::vector<char>& massless) const;
  // The mass with each node's listed directions massless ('Contact Mass' = normal:
  // Assembler::mass(directions)); not cached.
  RCP<const CrsMatrix> mass(const std::vector<std::vector<Point3>>& directions) const;
  // An upper bound of the highest eigenvalue of the stiffness() against the lumped mass():
  // Assembler::eigenvalueBound (+inf with a consistent mass). Collective.
  double eigenvalueBound() const { return assembler_->eigenvalueBound(springs_); }
  Kinematics kinematics() const { return kinematics_; }
  // Material of the block containing the node set's first node (for reference solutions).
  const Material& materialOfBlock(int block) const { return blockMaterial_[block]; }

  // The node set named `name`, or an InputError naming `parameter` and the valid names.
  const NodeSet& nodeSet(const std::string& name, const std::string& parameter) const;
  // The mesh blocks declared rigid ('Model/Blocks/<name>/Rigid'), by index.
  const std::vector<int>& rigidBlocks() const { return rigidBlocks_; }
  // Model/Couplings.
  const std::vector<ModelCoupling>& couplings() const { return couplings_; }
  // The held motion of the k-th rigid block (Model/Blocks/<name>/Held).
  const RigidHold& rigidHold(size_t k) const { return rigidHolds_[k]; }
  // Global DOF of (node, comp); -1 when that component is fixed or not carried.
  long long dof(int node, int comp) const { return dofs_->dof(node, comp); }

 private:
  std::string readMesh(const Teuchos::ParameterList& meshList);
  void handleCoincidentNodes(const Teuchos::ParameterList& meshList);
  std::vector<BlockPhysics> blockPhysics(const Teuchos::ParameterList& model);
  std::vector<std::uint8_t> freeComponents(const Teuchos::ParameterList& model,
                                           const std::vector<BlockPhysics>& physics) const;
  std::shared_ptr<const ElementKernel> blockKernel(const ElementBlock& blk, Kinematics kin,
                                                  const Material& m, const Teuchos::ParameterList& bp,
                                                  const std::string& file) const;
  // The block's finite-strain kernel (null for 'Strain' = 'small'), the material's 'Model'
  // checked against the block's 'Strain'.
  std::shared_ptr<const FiniteStrainSolid> strainKernel(const ElementBlock& blk, const Teuchos::ParameterList& bp,
                                                        const std::string& materialName,
                                                        const Teuchos::ParameterList& mp) const;
  // The block's 'Strain' against the kinematics its material's law runs on.
  void checkLawKinematics(const ElementBlock& blk, const MaterialLaw& law, bool finite,
                          const std::string& materialName) const;
  void checkOnePoint(const ElementBlock& blk, bool elementByElement) const;
  void checkElementGeometry(const std::vector<BlockPhysics>& physics, const std::string& meshParameter) const;
  void readSprings(const Teuchos::ParameterList& springs);
  void readCouplings(const Teuchos::ParameterList& couplings);
  void buildDofMap(std::vector<std::uint8_t> mask, const std::string& method);

  std::string inputFile_;
  RCP<const Comm> comm_;
  Kinematics kinematics_ = Kinematics::ThreeD;
  Mesh mesh_;
  std::vector<Material> blockMaterial_;
  std::unique_ptr<DofMap> dofs_;
  std::unique_ptr<Assembler> assembler_;
  std::vector<NodalSpring> springs_;  // Model/Springs, one per node
  std::vector<ModelCoupling> couplings_;  // Model/Couplings
  RCP<const CrsMatrix> K_, M_;
  std::vector<std::shared_ptr<const FiniteStrainSolid>> finite_;
  std::vector<std::shared_ptr<const ElementKernel>> kernels_;
  std::vector<int> rigidBlocks_;
  std::vector<RigidHold> rigidHolds_;  // per rigid block
};

}  // namespace choc
