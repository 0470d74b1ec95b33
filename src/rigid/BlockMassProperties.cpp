#include "rigid/BlockMassProperties.hpp"

#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>

#include "fem/ShapeFunctions.hpp"

namespace choc {

MassProperties blockMassProperties(const Mesh& mesh, const std::vector<int>& blocks,
                                   const std::vector<double>& densities, Kinematics kinematics,
                                   const std::vector<int>& elements, const Comm& comm,
                                   const std::vector<std::pair<Vec3, double>>& points) {
  if (blocks.size() != densities.size()) throw std::invalid_argument("blockMassProperties: one density per block");
  int first = -1;
  for (int b : blocks)
    if (mesh.blocks.at(size_t(b)).numElements() > 0) {
      first = mesh.blocks[size_t(b)].connectivity[0];
      break;
    }
  if (first < 0) throw std::invalid_argument("a rigid body whose blocks have no element");
  MassPropertiesSum sum(mesh.coords[size_t(first)]);
  std::vector<Vec3> x;
  for (int e : elements) {
    const auto [block, local] = mesh.locateElement(e);
    size_t k = 0;
    while (k < blocks.size() && blocks[k] != block) ++k;
    if (k == blocks.size()) continue;
    const ElementBlock& blk = mesh.blocks[size_t(block)];
    x.resize(size_t(blk.nodesPerElement));
    for (int a = 0; a < blk.nodesPerElement; ++a)
      x[size_t(a)] = mesh.coords[size_t(blk.connectivity[size_t(local * blk.nodesPerElement + a)])];
    sum.addElement(solidTopology(blk.topology), kinematics, x, densities[k]);
  }
  for (const auto& [p, m] : points) sum.addPoint(p, m);
  const std::vector<double> mine = sum.sums();
  std::vector<double> all(mine.size());
  Teuchos::reduceAll(comm, Teuchos::REDUCE_SUM, int(mine.size()), mine.data(), all.data());
  sum.setSums(all);
  return sum.properties();
}

}  // namespace choc
