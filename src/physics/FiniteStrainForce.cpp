// Finite-strain blocks element by element, the rest assembled (header).
#include "physics/FiniteStrainForce.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Vector.hpp>

#include "core/CollectiveFailure.hpp"
#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "core/Log.hpp"
#include "fem/ElementFrequencyBound.hpp"
#include "physics/Model.hpp"

namespace choc {

namespace {

std::vector<std::string> blockNamesOf(const Mesh& mesh) {
  std::vector<std::string> names;
  for (const auto& b : mesh.blocks) names.push_back(b.name);
  return names;
}

}  // namespace

FiniteStrainForce::FiniteStrainForce(Model& model)
    : K0_(model.stiffness()),
      Klin_(model.smallStrainStiffness()),
      states_(model.stiffness()->getComm(), blockNamesOf(model.mesh())),
      hourglass_(model.hasOnePointBlocks()),
      linearPart_(anyNonzero(*Klin_)) {
  KT_ = rcp(new CrsMatrix(K0_->getCrsGraph()));
  importer_ = K0_->getGraph()->getImporter();
  // The force's scratch vectors, made once: u on the column map, K_lin u, the u of the last force.
  if (!importer_.is_null()) uCol_ = rcp(new Vector(K0_->getColMap()));
  tmp_ = rcp(new Vector(K0_->getRowMap()));
  lastForce_.u = rcp(new Vector(K0_->getRowMap()));
  const Map& rows = *K0_->getRowMap();
  const Map& cols = *K0_->getColMap();
  const Mesh& mesh = model.mesh();
  const auto& kernels = model.finiteStrainKernels();
  for (size_t b = 0; b < mesh.blocks.size(); ++b) {
    blockNames_.push_back(mesh.blocks[b].name);
    finiteBlocks_.push_back(kernels[b] != nullptr);
  }
  numElements_ = mesh.numElements();
  threeD_ = model.kinematics() == Kinematics::ThreeD;
  for (int ge : model.localElements()) {
    const auto [b, e] = mesh.locateElement(ge);
    if (!kernels[size_t(b)]) continue;
    const ElementBlock& blk = mesh.blocks[size_t(b)];
    Element el{kernels[size_t(b)].get(), ge, b, false, {}, {}, {}, {}, {}, 0};
    std::vector<Point3> X;
    const int* conn = &blk.connectivity[size_t(e) * blk.nodesPerElement];
    const int nc = el.kernel->componentsPerNode();
    el.owner = model.dofs().ownerOfNode(conn[0]) == rows.getComm()->getRank();
    referenceAt_.push_back(reference_.size());
    for (int k = 0; k < blk.nodesPerElement; ++k) {
      X.push_back(mesh.coords[size_t(conn[k])]);
      reference_.insert(reference_.end(), X.back().begin(), X.back().end());
      for (int c = 0; c < nc; ++c) {
        const long long d = model.dof(conn[k], c);
        el.col.push_back(d < 0 ? LO(-1) : cols.getLocalElement(GO(d)));
        el.row.push_back(d < 0 ? LO(-1) : rows.getLocalElement(GO(d)));
      }
    }
    for (LO& r : el.row)
      if (r == Teuchos::OrdinalTraits<LO>::invalid()) r = -1;
    DenseMatrix M;
    model.elementKernel(b)->mass(X, MassKind::Lumped, M);
    el.geometry = el.kernel->geometry(X);
    el.roundoff = forceRoundoff(*el.kernel, el.geometry);
    for (int i = 0; i < M.rows(); ++i) el.lumpedMass.push_back(M(i, i));
    el.state = states_.add(*el.kernel, ge, b, el.owner);
    elements_.push_back(std::move(el));
  }
  states_.layout(mesh, kernels);
  layoutFields(kernels);
  packElements();
}

// The force streams through the elements with their next one prefetched and is bound by memory
// (without the prefetch the one-point Taylor quarter's force takes twice as long). Allocated
// while the elements were built, each element's arrays lay among the temporaries and the arrays
// the force does not read (the lumped mass, the round-off); copied here in element order, one
// after the other, the ones the force reads take fewer pages and lines (15 % less time for
// that force, the same results bit for bit).
void FiniteStrainForce::packElements() {
  struct Read {
    std::vector<double> weight, dNdX, N, radius, hourglass;
    std::vector<LO> col, row;
  };
  std::vector<Read> copies;
  copies.reserve(elements_.size());
  for (const Element& e : elements_) {
    const ElementGeometry& g = e.geometry;
    copies.push_back({g.weight, g.dNdX, g.N, g.radius, g.hourglass, e.col, e.row});
  }
  for (size_t k = 0; k < elements_.size(); ++k) {
    ElementGeometry& g = elements_[k].geometry;
    Read& c = copies[k];
    g.weight.swap(c.weight), g.dNdX.swap(c.dNdX), g.N.swap(c.N), g.radius.swap(c.radius);
    g.hourglass.swap(c.hourglass), elements_[k].col.swap(c.col), elements_[k].row.swap(c.row);
  }
}

// Whether K has a nonzero value on any rank (a model of finite-strain blocks alone has an all-zero
// linear part on the whole graph: its products are skipped).
bool FiniteStrainForce::anyNonzero(const CrsMatrix& K) {
  const auto A = K.getLocalMatrixHost();
  int mine = 0, any = 0;
  for (size_t k = 0; k < size_t(A.values.extent(0)) && !mine; ++k) mine = A.values(k) != 0.0;
  Teuchos::reduceAll<int, int>(*K.getComm(), Teuchos::REDUCE_MAX, mine, Teuchos::outArg(any));
  return any != 0;
}

// The strain E = (C - I) / 2 is computed from C = F^T F, whose entries are of size 1, so it
// errs by about eps whatever the deformation, and so does a stress written with C^-1 (the
// neo-Hookean mu (I - C^-1)): C's entries sum three products (3 eps), C^-1's cofactors and
// determinant add about 6 eps, so the stress errs by about 10 eps (lambda + 2 mu) (measured:
// a HEX20 beam at rest stagnates at 1.1 times the estimate made with 1 eps); node a's force
// by that times int |grad N_a| dV. termsNorm reports it in the units of its callers, who
// take 1e-12 of the terms' size as the round-off floor: times 10 eps / 1e-12.
std::vector<double> FiniteStrainForce::forceRoundoff(const FiniteStrainSolid& kernel, const ElementGeometry& g) {
  const double floor = 10.0 * std::numeric_limits<double>::epsilon() / 1e-12 * kernel.modulus();
  std::vector<double> r;
  for (int a = 0; a < g.nodes; ++a) {
    double s = 0.0;
    for (int q = 0; q < g.points; ++q)
      for (int J = 0; J < 3; ++J) s += g.weight[size_t(q)] * std::abs(g.dNdX[(size_t(q) * g.nodes + a) * 3 + J]);
    for (int c = 0; c < kernel.componentsPerNode(); ++c) r.push_back(floor * s);
  }
  return r;
}

const Vector& FiniteStrainForce::onColumns(const Vector& u) const {
  if (importer_.is_null()) return u;
  uCol_->doImport(u, *importer_, Tpetra::INSERT);
  return *uCol_;
}

std::string FiniteStrainForce::describe(const Element& e, const std::string& what) const {
  return "element " + std::to_string(e.number + 1) + " of block '" + blockNames_[size_t(e.block)] + "': " + what;
}

void FiniteStrainForce::throwIfFailed(const std::string& localFailure) const {
  const std::string failure = collectiveFailure(*K0_->getComm(), localFailure);
  if (!failure.empty()) throw InadmissibleState(failure);
}

void FiniteStrainForce::gather(const Element& e, const Teuchos::ArrayRCP<const double>& uCol,
                               std::vector<double>& ue) {
  ue.assign(e.col.size(), 0.0);
  for (size_t k = 0; k < e.col.size(); ++k)
    if (e.col[k] >= 0) ue[k] = uCol[e.col[k]];
}

namespace {

void prefetchBytes(const void* p, size_t bytes, bool forWriting) {
  const char* c = static_cast<const char*>(p);
  for (size_t b = 0; b < bytes; b += 64) {
    if (forWriting)
      __builtin_prefetch(c + b, 1);
    else
      __builtin_prefetch(c + b, 0);
  }
}

template <class T>
void prefetchVector(const std::vector<T>& v) {
  prefetchBytes(v.data(), v.size() * sizeof(T), false);
}

}  // namespace

// The next element's data on their way to the cache while this one is computed: each element's
// geometry, indices and state are separate allocations the hardware's prefetcher does not follow.
void FiniteStrainForce::prefetch(const Element& e, bool trial) const {
  const ElementGeometry& g = e.geometry;
  prefetchVector(g.dNdX), prefetchVector(g.weight), prefetchVector(g.hourglass), prefetchVector(e.col);
  prefetchVector(e.row);
  const size_t n = size_t(e.kernel->stateSize()) * sizeof(double);
  if (n == 0) return;
  prefetchBytes(states_.committed() + e.state, n, false);
  if (trial) prefetchBytes(states_.trial() + e.state, n, true);
}

template <class Visit>
std::string FiniteStrainForce::forEachElement(const Vector& uCol, bool withTangent, Visit&& visit, TrialPass* trial,
                                              bool elasticTangent) const {
  auto data = uCol.getData();
  std::vector<double> ue, fe;
  DenseMatrix Ke;
  const double dt = time_ - states_.committedTime();
  for (size_t k = 0; k < elements_.size(); ++k) {
    const Element& e = elements_[k];
    if (k + 1 < elements_.size()) prefetch(elements_[k + 1], trial != nullptr);
    gather(e, data, ue);
    double energy = 0.0, work = 0.0, hourglass = 0.0;
    try {
      energy = e.kernel->evaluate(e.geometry, ue, fe, withTangent ? &Ke : nullptr, states_.committed() + e.state,
                                  trial ? trial->state + e.state : nullptr, &work, elasticTangent, dt, &hourglass);
      if (trial && e.owner) trial->work += work, trial->hourglass += hourglass;
    } catch (const InvertedElement& err) {
      return describe(e, err.what());
    }
    visit(e, fe, Ke, energy);
  }
  return "";
}

bool FiniteStrainForce::sameState(const RCP<Vector>& at, const Vector& u) const {
  if (at.is_null()) return false;
  auto a = at->getData(), b = u.getData();
  int differ = 0;
  for (size_t i = 0; i < size_t(b.size()) && !differ; ++i) differ = a[i] != b[i];
  int any = 0;
  Teuchos::reduceAll<int, int>(*K0_->getComm(), Teuchos::REDUCE_MAX, differ, Teuchos::outArg(any));
  return any == 0;
}

void FiniteStrainForce::internalForce(const Vector& u, Vector& out) {
  if (linearPart_)
    Klin_->apply(u, out);
  else
    out.putScalar(0.0);
  auto o = out.getDataNonConst();
  double energy = 0.0;
  TrialPass pass{states_.trial()};
  const Vector& uc = onColumns(u);
  for (const auto& p : followers_) p->subtractForce(uc.getData(), time_, o);
  const std::string failure = forEachElement(uc, false, [&](const Element& e, const std::vector<double>& f,
                                                                      const DenseMatrix&, double w) {
    for (size_t k = 0; k < e.row.size(); ++k)
      if (e.row[k] >= 0) o[e.row[k]] += f[k];
    if (e.owner) energy += w;
  }, &pass);
  states_.trialWritten(failure.empty(), time_, pass.work);
  throwIfFailed(failure);
  lastForce_.u->assign(u);
  lastForce_.valid = true;
  lastForce_.energy = energy;
  lastForce_.hourglass = pass.hourglass;
}

RCP<const CrsMatrix> FiniteStrainForce::tangent(const Vector& u) {
  if (tangentValid_ && tangentTime_ == time_ && sameState(tangentAt_, u)) return KT_;  // those at u already
  KT_->resumeFill();
  {
    const auto A = KT_->getLocalMatrixHost();
    const auto L = Klin_->getLocalMatrixHost();  // the same graph: the same value slots
    for (size_t k = 0; k < size_t(A.values.extent(0)); ++k) A.values(k) = L.values(k);
  }
  std::vector<LO> cols;
  std::vector<double> vals;
  const Vector& uc = onColumns(u);
  for (const auto& p : followers_) p->addTangent(uc.getData(), time_, *KT_);
  const std::string failure = forEachElement(uc, true, [&](const Element& e, const std::vector<double>&,
                                                                     const DenseMatrix& K, double) {
    for (size_t i = 0; i < e.row.size(); ++i) {
      if (e.row[i] < 0) continue;
      cols.clear();
      vals.clear();
      for (size_t j = 0; j < e.col.size(); ++j)
        if (e.col[j] >= 0) cols.push_back(e.col[j]), vals.push_back(K(int(i), int(j)));
      const LO found =
          KT_->sumIntoLocalValues(e.row[i], Teuchos::ArrayView<const LO>(cols), Teuchos::ArrayView<const double>(vals));
      if (size_t(found) != cols.size())  // the graph has every entry of these blocks (BlockPhysics::fullPattern)
        throw std::logic_error(describe(e, "tangent entries outside the stiffness' graph"));
    }
  });
  KT_->fillComplete(K0_->getDomainMap(), K0_->getRangeMap());
  ++version_;
  if (tangentAt_.is_null()) tangentAt_ = rcp(new Vector(u.getMap()));
  tangentAt_->assign(u);
  tangentTime_ = time_;
  tangentValid_ = failure.empty();
  throwIfFailed(failure);
  return KT_;
}

double FiniteStrainForce::strainEnergy(const Vector& u, const Vector* /*internalForceAtU*/) const {
  double linear = 0.0;
  if (linearPart_) {
    Klin_->apply(u, *tmp_);
    linear = 0.5 * u.dot(*tmp_);
  }
  double local = 0.0;
  if (lastForce_.valid && sameState(lastForce_.u, u)) {
    local = lastForce_.energy;
  } else {
    const std::string failure = forEachElement(onColumns(u), false, [&](const Element& e, const std::vector<double>&,
                                                                        const DenseMatrix&, double energy) {
      if (e.owner) local += energy;
    });
    throwIfFailed(failure);
  }
  double global = 0.0;
  Teuchos::reduceAll<int, double>(*K0_->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return linear + global;
}

double FiniteStrainForce::hourglassEnergy(const Vector& u) const {
  if (!hourglass_) return 0.0;  // the same on every rank (the model's blocks)
  double local = 0.0, global = 0.0;
  if (lastForce_.valid && sameState(lastForce_.u, u)) {  // the internal force at u summed it already
    local = lastForce_.hourglass;
  } else {
    auto data = onColumns(u).getData();
    std::vector<double> ue;
    for (const Element& e : elements_) {
      if (!e.owner || !e.kernel->onePoint()) continue;
      gather(e, data, ue);
      local += e.kernel->hourglassEnergy(e.geometry, ue);
    }
  }
  Teuchos::reduceAll<int, double>(*K0_->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return global;
}

// || |K_lin| |u| + sum_e |f_e| ||: the size of the terms the internal force sums, row by row.
double FiniteStrainForce::termsNorm(const Vector& u) const {
  const Vector& uc = onColumns(u);
  auto ud = uc.getData();
  const auto A = Klin_->getLocalMatrixHost();
  const size_t nRows = size_t(A.graph.row_map.extent(0)) - 1;
  std::vector<double> terms(nRows, 0.0);
  for (size_t i = 0; i < nRows; ++i)
    for (auto k = A.graph.row_map(i); k < A.graph.row_map(i + 1); ++k)
      terms[i] += std::abs(A.values(k)) * std::abs(ud[A.graph.entries(k)]);
  const std::string failure = forEachElement(uc, false, [&](const Element& e, const std::vector<double>& f,
                                                            const DenseMatrix&, double) {
    for (size_t k = 0; k < e.row.size(); ++k)
      if (e.row[k] >= 0) terms[size_t(e.row[k])] += std::abs(f[k]) + e.roundoff[k];
  });
  throwIfFailed(failure);
  double local = 0.0;
  for (double t : terms) local += t * t;
  double global = 0.0;
  Teuchos::reduceAll<int, double>(*K0_->getComm(), Teuchos::REDUCE_SUM, local, Teuchos::outArg(global));
  return std::sqrt(global);
}

double FiniteStrainForce::stateEigenvalueBound(const Vector& u) const {
  ElementEigenvalueMaximum maximum;
  std::vector<char> active;
  const std::string failure = forEachElement(onColumns(u), true, [&](const Element& e, const std::vector<double>&,
                                                                     const DenseMatrix& K, double) {
    active.resize(e.col.size());
    for (size_t i = 0; i < e.col.size(); ++i) active[i] = e.col[i] >= 0;
    maximum.add(K, e.lumpedMass, active);
  }, nullptr, true);
  throwIfFailed(failure);
  const double local = maximum.value();
  double global = 0.0;
  Teuchos::reduceAll<int, double>(*K0_->getComm(), Teuchos::REDUCE_MAX, local, Teuchos::outArg(global));
  return global;
}

std::vector<std::string> FiniteStrainForce::elementFieldNames() const {
  std::vector<std::string> names = {"SIGMA_XX", "SIGMA_YY", "SIGMA_ZZ", "SIGMA_XY"};
  if (threeD_) names.insert(names.end(), {"SIGMA_YZ", "SIGMA_ZX"});
  names.push_back("STRAIN_ENERGY_DENSITY");
  names.insert(names.end(), materialFields_.begin(), materialFields_.end());
  return names;
}

void FiniteStrainForce::elementFields(const Vector& u, std::vector<std::vector<double>>& values) const {
  const size_t stresses = threeD_ ? 6 : 4;
  values.assign(elementFieldNames().size(), std::vector<double>(size_t(numElements_), 0.0));
  const Vector& uc = onColumns(u);
  auto data = uc.getData();
  std::string failure;
  std::vector<double> ue, fields;
  std::array<double, 6> sigma{};
  double w = 0.0;
  for (const Element& e : elements_) {
    if (!e.owner) continue;
    gather(e, data, ue);
    try {
      e.kernel->averageStress(e.geometry, ue, sigma, w, states_.committed() + e.state, &fields);
    } catch (const InvertedElement& err) {
      failure = describe(e, err.what());
      break;
    }
    for (size_t c = 0; c < stresses; ++c) values[c][size_t(e.number)] = sigma[c];
    values[stresses][size_t(e.number)] = w;
    const std::vector<size_t>& at = blockFields_[size_t(e.block)];
    for (size_t k = 0; k < fields.size(); ++k) values[stresses + 1 + at[k]][size_t(e.number)] = fields[k];
  }
  throwIfFailed(failure);
}

// The union of the blocks' material fields in the order they first appear, and each block's
// fields' places in it.
void FiniteStrainForce::layoutFields(const std::vector<std::shared_ptr<const FiniteStrainSolid>>& kernels) {
  blockFields_.assign(kernels.size(), {});
  for (size_t b = 0; b < kernels.size(); ++b) {
    if (!kernels[b]) continue;
    for (const std::string& name : kernels[b]->material().fieldNames()) {
      auto it = std::find(materialFields_.begin(), materialFields_.end(), name);
      if (it == materialFields_.end()) it = materialFields_.insert(materialFields_.end(), name);
      blockFields_[b].push_back(size_t(it - materialFields_.begin()));
    }
  }
}

}  // namespace choc
