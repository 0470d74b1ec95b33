// Assembly of global matrices into Tpetra CRS matrices on the DofMap's distribution.
// Each rank computes every element that touches one of its nodes and keeps the rows it owns:
// the few boundary elements are computed twice, no entries travel between ranks, and every row
// is summed in global element order, so the matrices are bitwise identical on any rank count.
#pragma once
#include <functional>
#include <memory>
#include <vector>

#include "fem/DofMap.hpp"
#include "fem/ElementKernel.hpp"
#include "core/TpetraTypes.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

struct BlockPhysics {
  std::shared_ptr<const ElementKernel> kernel;  // nullptr: the block carries no unknowns
  MassKind mass = MassKind::Consistent;
  // Every pair of an element's DOFs is an entry of the stiffness' graph, zero or not: a block
  // whose tangent later fills entries its small-strain stiffness leaves exactly zero (finite
  // strain: nu = 0 zeroes the coupling of u_x and u_y terms a rotation brings back, and so do
  // the symmetries of regular meshes). Without it they would be dropped silently.
  bool fullPattern = false;
  // The block moves as a rigid body (physics/RigidBodies.hpp): its elements give mass (its
  // nodes' lumped masses weigh their initial velocities) and no stiffness.
  bool rigid = false;
};

// Mass redistribution (Khenous, Laborde, Renard 2008, "Mass redistribution method for finite
// element contact problems in elastodynamics"): the element mass matrix Me (nodes x, nc
// components per node, node-major) becomes T^T Me T, where T copies every node's motion except
// that of a massless node, which follows the mean of its nearest non-massless nodes of the
// element (a partition of unity with non-negative weights). Hence: the massless nodes' rows and
// columns are zero; the element mass 1_c^T Me 1_c of every component c is kept exactly (T 1 =
// 1); the matrix stays symmetric positive semi-definite; a lumped matrix is re-lumped (row sums)
// so it stays diagonal. Where the nearest node is the translate of the massless node along the
// element edge across the surface (extruded meshes, as SDNL111's), the centre of mass is kept
// in the surface's plane; across it, the element's share moves to the far nodes (by at most
// one element size). Throws std::invalid_argument when every node of the element is massless.
void redistributeElementMass(const std::vector<Point3>& x, const std::vector<char>& massless,
                             int nc, MassKind kind, DenseMatrix& Me);

// A linear spring from a node to a fixed point (grounded): stiffness k along the unit
// direction d, k d d^T on the node's translations (components fixed or not carried drop out).
struct NodalSpring {
  int node = 0;
  Point3 direction{};
  double stiffness = 0.0;
};

class Assembler {
 public:
  Assembler(const Mesh& mesh, const DofMap& dofs, std::vector<BlockPhysics> blocks,
            RCP<const Comm> comm);

  RCP<const Map> map() const { return map_; }
  // Groups of nodes whose DOFs the stiffness' graph couples, each with every other of its group
  // (zero entries: a coupling's load stiffness is added there). Before the first assembly.
  void coupleNodes(std::vector<std::vector<int>> groups) { groups_ = std::move(groups); }
  // The elements' stiffness, plus the springs' k d d^T summed after them.
  RCP<CrsMatrix> stiffness(const std::vector<NodalSpring>& springs = {}) const;
  // The stiffness of the blocks not flagged in `skip` (one flag per mesh block) plus the
  // springs, on `graph` (that of stiffness(springs)): the entries only skipped blocks give are
  // present and zero. The linear part of a model whose flagged blocks are computed otherwise
  // (finite strain), on the graph their tangent is added into. Rigid blocks give no stiffness
  // here nor in stiffness().
  RCP<CrsMatrix> stiffnessWithout(const std::vector<char>& skip, const std::vector<NodalSpring>& springs,
                                  const RCP<const Tpetra::CrsGraph<LO, GO>>& graph) const;
  RCP<CrsMatrix> mass() const;
  // The mass with the nodes flagged in `massless` (one entry per mesh node) carrying none: each
  // element touching them has its mass redistributed onto its other nodes
  // (redistributeElementMass). Computed element by element like mass(), so it is the same on
  // any number of ranks. Throws std::invalid_argument for a wrong-sized mask or an element
  // whose nodes are all massless.
  RCP<CrsMatrix> mass(const std::vector<char>& massless) const;
  // The mass with the nodes' listed directions (one list per mesh node, empty for most) carrying
  // none: 'Contact Mass' = normal (removeNormalMass, fem/NormalMassRemoval.hpp). Throws
  // std::invalid_argument for a wrong-sized list or an element whose nodes all have directions.
  RCP<CrsMatrix> mass(const std::vector<std::vector<Point3>>& directions) const;
  // An upper bound of the highest eigenvalue of K x = lambda M x (the stiffness with `springs`,
  // the lumped mass): the largest element eigenvalue (elementEigenvalue, Irons and Treharne)
  // plus Gershgorin's bound of the springs alone on the nodes' lumped masses. +inf when a block
  // has a consistent mass or an element's lumped mass is not positive where it is stiff.
  // Collective; the same on any number of ranks.
  double eigenvalueBound(const std::vector<NodalSpring>& springs = {}) const;
  // Components each node carries through the elements attached to it (bit mask per node).
  static std::vector<std::uint8_t> carriedComponents(const Mesh& mesh,
                                                     const std::vector<BlockPhysics>& blocks);
  // Elements (global indices) computed on this rank, in global order.
  const std::vector<int>& localElements() const { return elements_; }

 private:
  using ElementMatrixFn = std::function<void(const ElementKernel&, MassKind, const std::vector<Point3>&,
                                             const int* conn, DenseMatrix&)>;
  // On `graph` when given (else the graph of the nonzero entries, and with fullPatterns every
  // entry of the blocks flagged BlockPhysics::fullPattern).
  RCP<CrsMatrix> assemble(const ElementMatrixFn& fn, const std::vector<NodalSpring>& springs = {},
                          RCP<const Tpetra::CrsGraph<LO, GO>> graph = Teuchos::null, bool fullPatterns = false,
                          bool coupled = false) const;
  // One element this rank computes: its block's physics, nodes, coordinates and the global DOF
  // of each (node, component) in element order (-1: fixed or not carried).
  struct LocalElement {
    const BlockPhysics* physics = nullptr;
    const int* conn = nullptr;
    std::vector<Point3> x;
    std::vector<long long> gdof;
  };
  // coupled: the stiffness, whose graph couples the node groups (coupleNodes); not the mass.
  void extraRows(const std::vector<NodalSpring>& springs, bool coupled, std::vector<GO>& cols, std::vector<double>& vals,
                 const std::function<void(int)>& visit) const;
  // Calls fn for every element this rank computes, in global order (one LocalElement reused).
  void forEachElement(const std::function<void(const LocalElement&)>& fn) const;

  const Mesh& mesh_;
  const DofMap& dofs_;
  std::vector<BlockPhysics> blocks_;
  std::vector<std::vector<int>> groups_;  // coupleNodes
  RCP<const Comm> comm_;
  RCP<const Map> map_;
  std::vector<int> elements_;
};

}  // namespace choc
