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
#include "fem/TpetraTypes.hpp"
#include "mesh/Mesh.hpp"

namespace choc {

struct BlockPhysics {
  std::shared_ptr<const ElementKernel> kernel;  // nullptr: the block carries no unknowns
  MassKind mass = MassKind::Consistent;
};

class Assembler {
 public:
  Assembler(const Mesh& mesh, const DofMap& dofs, std::vector<BlockPhysics> blocks,
            RCP<const Comm> comm);

  RCP<const Map> map() const { return map_; }
  RCP<CrsMatrix> stiffness() const;
  RCP<CrsMatrix> mass() const;
  // Components each node carries through the elements attached to it (bit mask per node).
  static std::vector<std::uint8_t> carriedComponents(const Mesh& mesh,
                                                     const std::vector<BlockPhysics>& blocks);
  // Elements (global indices) computed on this rank, in global order.
  const std::vector<int>& localElements() const { return elements_; }

 private:
  using ElementMatrixFn =
      std::function<void(const ElementKernel&, MassKind, const std::vector<Point3>&, DenseMatrix&)>;
  RCP<CrsMatrix> assemble(const ElementMatrixFn& fn) const;

  const Mesh& mesh_;
  const DofMap& dofs_;
  std::vector<BlockPhysics> blocks_;
  RCP<const Comm> comm_;
  RCP<const Map> map_;
  std::vector<int> elements_;
};

}  // namespace choc
