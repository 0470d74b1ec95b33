#include "solvers/ElasticityMultigrid.hpp"

#include <MueLu_CreateTpetraPreconditioner.hpp>
#include <MueLu_TpetraOperator.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Tpetra_Vector.hpp>

#include "core/Errors.hpp"
#include "core/Memory.hpp"

namespace choc {

using Node = Map::node_type;
using MueLuOperator = MueLu::TpetraOperator<double, LO, GO, Node>;

struct ElasticityMultigrid::Hierarchy {
  RCP<MueLuOperator> op;
};

namespace {

// Smoothed aggregation for a vector problem: aggregates of whole nodes (the block size),
// neighbours coupled by less than 0.02 of the diagonals' geometric mean dropped from the
// aggregation graph, the rigid-body modes as the near-null space, degree-2 Chebyshev smoothing
// (symmetric, and the same on any number of ranks: matrix products only), and on the coarsest
// level (at most 300 rows) ten symmetric Gauss-Seidel sweeps (Debian's Amesos2 KLU2, MueLu's
// direct coarse solver, is wrong on more than one rank: Amesos2RootBackend.cpp). Measured on the
// scale scene's bars at 153,792 unknowns and theta 119,000 (docs/performance/multigrid.md):
// 33 CG iterations per solve; Chebyshev of degree 1 takes 52 and degree 3 37 (slower), one
// symmetric Gauss-Seidel sweep 35 (slower), no dropping 37.
Teuchos::ParameterList mueluParameters(const NodalBlocks& b, const RCP<MultiVector>& nullspace) {
  Teuchos::ParameterList p;
  p.set("verbosity", "none");
  p.set("problem: symmetric", true);
  p.set("multigrid algorithm", "sa");
  p.set("number of equations", b.blockSize);
  p.set("aggregation: type", "uncoupled");
  p.set("aggregation: drop tol", 0.02);
  p.set("sa: use filtered matrix", false);
  p.set("smoother: type", "CHEBYSHEV");
  p.sublist("smoother: params").set("chebyshev: degree", 2);
  p.set("coarse: max size", 300);
  p.set("coarse: type", "RELAXATION");
  Teuchos::ParameterList& cp = p.sublist("coarse: params");
  cp.set("relaxation: type", "Symmetric Gauss-Seidel");
  cp.set("relaxation: sweeps", 10);
  p.set("repartition: enable", false);
  p.sublist("user data").set("Nullspace", nullspace);
  return p;
}

}  // namespace

ElasticityMultigrid::ElasticityMultigrid(std::shared_ptr<const NodalBlocks> blocks)
    : blocks_(std::move(blocks)) {}

ElasticityMultigrid::~ElasticityMultigrid() = default;

void ElasticityMultigrid::buildBlockMatrix(const CrsMatrix& A) {
  const NodalBlocks& b = *blocks_;
  map_ = A.getRowMap();
  blockMap_ = rcp(new Map(Tpetra::global_size_t(b.numGlobalBlocks * b.blockSize),
                          size_t(b.numOwnedRows()), 0, A.getRowMap()->getComm()));
  const GO first = b.firstOwnedBlock * b.blockSize;
  if (b.numOwnedRows() > 0 && blockMap_->getMinGlobalIndex() != first)
    throw NumericalError("Multigrid: the node blocks are not numbered in rank order");
  const auto L = A.getLocalMatrixHost();
  const auto colMap = A.getColMap();
  const LO nRows = LO(A.getNodeNumRows());
  blockRowOfRow_.assign(nRows, 0);
  std::vector<char> held(b.numOwnedRows(), 0);
  size_t widest = 1;
  const auto blockRow = [&](GO dof) {
    if (dof < 0 || dof >= GO(b.blockRowOfDof.size()) || b.blockRowOfDof[dof] < 0)
      throw NumericalError("Multigrid: row " + std::to_string(dof) + " of the matrix is not a nodal unknown");
    return b.blockRowOfDof[dof];
  };
  for (LO i = 0; i < nRows; ++i) {
    blockRowOfRow_[i] = LO(blockRow(map_->getGlobalElement(i)) - first);
    held[blockRowOfRow_[i]] = 1;
    widest = std::max(widest, size_t(L.graph.row_map(i + 1) - L.graph.row_map(i)));
  }
  blockA_ = rcp(new CrsMatrix(blockMap_, widest));
  std::vector<GO> cols;
  std::vector<double> vals;
  for (LO i = 0; i < nRows; ++i) {
    cols.clear();
    vals.clear();
    for (auto k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k) {
      cols.push_back(blockRow(colMap->getGlobalElement(L.graph.entries(k))));
      vals.push_back(L.values(k));
    }
    blockA_->insertGlobalValues(first + blockRowOfRow_[i], Teuchos::ArrayView<const GO>(cols),
                                Teuchos::ArrayView<const double>(vals));
  }
  fixedRows_.clear();
  const double one = 1.0;
  for (LO r = 0; r < LO(held.size()); ++r)
    if (!held[r]) {
      fixedRows_.push_back(r);
      const GO g = first + r;
      blockA_->insertGlobalValues(g, Teuchos::ArrayView<const GO>(&g, 1), Teuchos::ArrayView<const double>(&one, 1));
    }
  blockA_->fillComplete(blockMap_, blockMap_);
  const auto bcol = blockA_->getColMap();
  blockColOfEntry_.resize(L.values.extent(0));
  for (LO i = 0; i < nRows; ++i)
    for (auto k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k)
      blockColOfEntry_[k] = bcol->getLocalElement(b.blockRowOfDof[colMap->getGlobalElement(L.graph.entries(k))]);
  graph_ = A.getCrsGraph().get();
}

// A's values into the node-by-node matrix; a fixed component's row gets the mean diagonal of
// its node's free components (a scale like its neighbours', so smoothing treats it alike).
void ElasticityMultigrid::refillBlockMatrix(const CrsMatrix& A) {
  const NodalBlocks& b = *blocks_;
  const auto L = A.getLocalMatrixHost();
  blockA_->resumeFill();
  Vector diagonal(map_);
  A.getLocalDiagCopy(diagonal);
  const auto d = diagonal.getData();
  std::vector<double> diagonalSum(b.numOwnedBlocks, 0.0);
  std::vector<int> freeCount(b.numOwnedBlocks, 0);
  for (LO i = 0; i < LO(blockRowOfRow_.size()); ++i) {
    const auto begin = L.graph.row_map(i), end = L.graph.row_map(i + 1);
    const LO row = blockRowOfRow_[i];
    blockA_->replaceLocalValues(row, Teuchos::ArrayView<const LO>(&blockColOfEntry_[begin], end - begin),
                                Teuchos::ArrayView<const double>(&L.values(begin), end - begin));
    diagonalSum[row / b.blockSize] += d[i];
    ++freeCount[row / b.blockSize];
  }
  const GO first = b.firstOwnedBlock * b.blockSize;
  for (LO r : fixedRows_) {
    const int node = r / b.blockSize;
    const double d = freeCount[node] > 0 ? diagonalSum[node] / freeCount[node] : 1.0;
    const LO c = blockA_->getColMap()->getLocalElement(first + r);
    blockA_->replaceLocalValues(r, Teuchos::ArrayView<const LO>(&c, 1), Teuchos::ArrayView<const double>(&d, 1));
  }
  blockA_->fillComplete(blockMap_, blockMap_);
}

void ElasticityMultigrid::compute(const RCP<const CrsMatrix>& A) {
  try {
    hierarchy_.reset();  // the old hierarchy's memory first
    if (blockA_.is_null() || A->getCrsGraph().get() != graph_) {
      blockA_ = Teuchos::null;
      buildBlockMatrix(*A);
    }
    refillBlockMatrix(*A);
    const std::vector<double> modes = blocks_->rigidBodyModes();
    const size_t rows = blocks_->numOwnedRows(), nModes = blocks_->numRigidModes();
    auto nullspace = rcp(new MultiVector(blockMap_, nModes));
    for (size_t m = 0; m < nModes; ++m) {
      auto col = nullspace->getDataNonConst(m);
      for (size_t i = 0; i < rows; ++i) col[i] = modes[m * rows + i];
    }
    Teuchos::ParameterList p = mueluParameters(*blocks_, nullspace);
    hierarchy_ = std::make_unique<Hierarchy>();
    hierarchy_->op = MueLu::CreateTpetraPreconditioner<double, LO, GO, Node>(RCP<Operator>(blockA_), p);
    ++builds_;
  } catch (const NumericalError&) {
    throw;
  } catch (const std::exception& e) {
    hierarchy_.reset();
    rethrowIfOutOfMemory(describeFailure(e), "MueLu multigrid");
    throw NumericalError("MueLu multigrid set-up failed: " + std::string(e.what()).substr(0, 200));
  }
}

void ElasticityMultigrid::apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp, double alpha,
                                double beta) const {
  const size_t nv = X.getNumVectors();
  if (bx_.is_null() || bx_->getNumVectors() != nv) {
    bx_ = rcp(new MultiVector(blockMap_, nv));
    by_ = rcp(new MultiVector(blockMap_, nv));
  }
  bx_->putScalar(0.0);
  for (size_t c = 0; c < nv; ++c) {
    auto x = X.getData(c);
    auto bx = bx_->getDataNonConst(c);
    for (size_t i = 0; i < blockRowOfRow_.size(); ++i) bx[blockRowOfRow_[i]] = x[i];
  }
  hierarchy_->op->apply(*bx_, *by_);
  for (size_t c = 0; c < nv; ++c) {
    auto by = by_->getData(c);
    auto y = Y.getDataNonConst(c);
    for (size_t i = 0; i < blockRowOfRow_.size(); ++i)
      y[i] = (beta == 0.0 ? 0.0 : beta * y[i]) + alpha * by[blockRowOfRow_[i]];
  }
}

int ElasticityMultigrid::levels() const {
  return hierarchy_ ? hierarchy_->op->GetHierarchy()->GetNumLevels() : 0;
}

std::string ElasticityMultigrid::description() const {
  return "MueLu smoothed aggregation (" + std::to_string(blocks_->blockSize) + " components per node, " +
         std::to_string(blocks_->numRigidModes()) + " rigid-body modes, " + std::to_string(levels()) +
         " levels)";
}

}  // namespace choc
