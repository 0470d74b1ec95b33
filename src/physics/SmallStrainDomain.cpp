#include "physics/SmallStrainDomain.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/CollectiveFailure.hpp"
#include "physics/Model.hpp"

namespace choc {

SmallStrainDomain::SmallStrainDomain(Model& model) {
  const RCP<const CrsMatrix> K = model.stiffness();
  columns_ = K->getColMap();
  importer_ = K->getGraph()->getImporter();
  if (!importer_.is_null()) uCol_ = rcp(new Vector(columns_));  // u on the column map (scratch, made once)
  const Mesh& mesh = model.mesh();
  const auto& kernels = model.finiteStrainKernels();
  const int rank = K->getComm()->getRank();
  static const QuadratureRule centreOnly;  // the strain is judged at the centre alone
  for (const ElementBlock& b : mesh.blocks) blockNames_.push_back(b.name);
  std::vector<char> rigid(mesh.blocks.size(), 0);  // a rigid block's elements have no strain
  for (int b : model.rigidBlocks()) rigid[size_t(b)] = 1;
  for (int ge : model.localElements()) {
    const auto [b, e] = mesh.locateElement(ge);
    const ElementBlock& blk = mesh.blocks[size_t(b)];
    SolidShape shape{};
    if (kernels[size_t(b)] || rigid[size_t(b)] || !findSolidTopology(blk.topology, shape)) continue;
    const int* conn = &blk.connectivity[size_t(e) * size_t(blk.nodesPerElement)];
    if (model.dofs().ownerOfNode(conn[0]) != rank) continue;
    Element el{ge, b, &checkPoints(shape, centreOnly, false), model.kinematics() == Kinematics::ThreeD ? 3 : 2,
               model.kinematics() == Kinematics::Axisymmetric, {}, {}};
    for (int k = 0; k < blk.nodesPerElement; ++k) {
      el.X.push_back(mesh.coords[size_t(conn[k])]);
      for (int c = 0; c < el.nc; ++c) {
        const long long d = model.dof(conn[k], c);
        const LO l = d < 0 ? LO(-1) : columns_->getLocalElement(GO(d));
        el.col.push_back(l == Teuchos::OrdinalTraits<LO>::invalid() ? LO(-1) : l);
      }
    }
    elements_.push_back(std::move(el));
  }
  const long long mine = static_cast<long long>(elements_.size());
  Teuchos::reduceAll<int, long long>(*K->getComm(), Teuchos::REDUCE_SUM, mine, Teuchos::outArg(elementsOnAnyRank_));
}

void SmallStrainDomain::check(const Vector& u, ElementValidity& v) const {
  if (empty() || !v.failure.empty()) return;
  const Vector* onColumns = &u;
  if (!importer_.is_null()) {
    uCol_->doImport(u, *importer_, Tpetra::INSERT);
    onColumns = uCol_.get();
  }
  auto data = onColumns->getData();
  std::vector<double> ue;
  ElementMeasure strain, rotation;
  for (const Element& e : elements_) {
    ue.assign(e.col.size(), 0.0);
    for (size_t k = 0; k < e.col.size(); ++k)
      if (e.col[k] >= 0) ue[k] = data[e.col[k]];
    const auto [eps, omega] = smallStrainAtCentre(*e.points, e.X, ue, e.nc, e.axisymmetric);
    keepWorst(strain, eps, e.number, false);
    keepWorst(rotation, omega, e.number, false);
  }
  const Comm& comm = *u.getMap()->getComm();
  strain = worstOverRanks(comm, strain, false);
  rotation = worstOverRanks(comm, rotation, false);
  const SmallStrainVerdict w = smallStrainVerdict(strain.value, strain.element >= 0, rotation.value, rotation.element >= 0);
  if (w.text.empty() || (!w.failed && !v.warning.empty())) return;
  const int worst = (w.strain ? strain : rotation).element;
  std::string line;
  for (const Element& e : elements_)
    if (e.number == worst)
      line = "element " + std::to_string(e.number + 1) + " of block '" + blockNames_[size_t(e.block)] + "': " + w.text;
  line = collectiveFailure(comm, line);
  (w.failed ? v.failure : v.warning) = line;
}

}  // namespace choc
