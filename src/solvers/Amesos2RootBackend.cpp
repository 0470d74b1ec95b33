// The Amesos2 backend: the system factored on rank 0 (see FactorizationBackend.hpp).
#include <Amesos2.hpp>
#include <Teuchos_CommHelpers.hpp>
#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/CollectiveFailure.hpp"
#include "core/Memory.hpp"
#include "solvers/FactorizationBackend.hpp"

namespace choc {

namespace {

// Amesos2 on a matrix whose communicator is MPI_COMM_SELF. (Debian's Trilinos 13.2 KLU2
// returns wrong solutions whenever the communicator has more than one rank, even with every
// row on rank 0 — see tests/unit/test_solvers_mpi_direct.cpp — so choc gathers the system to
// rank 0 itself and factors it there, which is what Amesos2 does internally for KLU2.)
class SerialFactorization {
 public:
  explicit SerialFactorization(std::string package) : package_(std::move(package)) {}
  void factor(RCP<const CrsMatrix> A) {
    if (solver_.is_null() || A.get() != A_.get()) {
      solver_ = Amesos2::create<CrsMatrix, MultiVector>(package_, A);
      solver_->symbolicFactorization();
    }
    A_ = A;
    solver_->numericFactorization();
  }
  // The entries of the factors L and U (KLU2 and the packages that report them; else 0).
  double factorEntries() const { return solver_.is_null() ? 0.0 : double(solver_->getStatus().getNnzLU()); }
  void solve(const MultiVector& b, MultiVector& x) {
    solver_->solve(Teuchos::ptr(&x), Teuchos::ptr(&b));
  }

 private:
  std::string package_;
  RCP<const CrsMatrix> A_;
  RCP<Amesos2::Solver<CrsMatrix, MultiVector>> solver_;
};

void copyLocal(const MultiVector& from, MultiVector& to) {
  for (size_t j = 0; j < from.getNumVectors(); ++j) {
    auto src = from.getData(j);
    auto dst = to.getDataNonConst(j);
    for (size_t i = 0; i < from.getLocalLength(); ++i) dst[i] = src[i];
  }
}

class Amesos2RootBackend : public FactorizationBackend {
 public:
  explicit Amesos2RootBackend(std::string package) : package_(package), serial_(std::move(package)) {}

  // On more than one rank only rank 0 factors: its failure is shared (CollectiveFailure.hpp)
  // so that every rank reports it, none waits in the next solve.
  std::string factor(RCP<const CrsMatrix> A) override {
    std::string failure;
    try {
      A_ = A;
      if (A->getComm()->getSize() == 1) {
        serial_.factor(A);
      } else {
        gatherToRoot(*A);
        if (A->getComm()->getRank() == 0) serial_.factor(rootSerial_);
      }
    } catch (const std::exception& e) {
      failure = describeFailure(e);
    }
    failure = collectiveFailure(*A->getComm(), failure);
    // Rank 0's count on every rank: the kept factorisation's budget is decided alike everywhere.
    factorEntries_ = A->getComm()->getRank() == 0 && failure.empty() ? serial_.factorEntries() : 0.0;
    Teuchos::broadcast(*A->getComm(), 0, &factorEntries_);
    return failure;
  }

  double countedFactorEntries() const override { return factorEntries_; }

  // One solve with the factorisation (gathered to rank 0 on several ranks).
  std::string solve(const MultiVector& b, MultiVector& x) override {
    std::string failure;
    if (A_->getComm()->getSize() == 1) {
      try {
        serial_.solve(b, x);
      } catch (const std::exception& e) {
        failure = describeFailure(e);
      }
      rethrowIfOutOfMemory(failure, "direct solver " + package_ + ": solve");
      return failure;
    }
    MultiVector bRoot(rootMap_, b.getNumVectors()), xRoot(rootMap_, b.getNumVectors());
    bRoot.doImport(b, *importer_, Tpetra::INSERT);
    if (A_->getComm()->getRank() == 0) {
      try {
        MultiVector bs(serialMap_, b.getNumVectors()), xs(serialMap_, b.getNumVectors());
        copyLocal(bRoot, bs);
        serial_.solve(bs, xs);
        copyLocal(xs, xRoot);
      } catch (const std::exception& e) {
        failure = describeFailure(e);
      }
    }
    x.doExport(xRoot, *importer_, Tpetra::INSERT);
    failure = collectiveFailure(*A_->getComm(), failure);
    rethrowIfOutOfMemory(failure, "direct solver " + package_ + ": solve");
    return failure;
  }

  std::string name() const override { return "Amesos2 " + package_; }

 private:
  // Copies A to rank 0, then into a matrix on MPI_COMM_SELF there.
  void gatherToRoot(const CrsMatrix& A) {
    auto comm = A.getComm();
    const Tpetra::global_size_t n = A.getGlobalNumRows();
    if (rootMap_.is_null() || rootMap_->getGlobalNumElements() != n) {
      rootMap_ = rcp(new Map(n, comm->getRank() == 0 ? size_t(n) : 0, 0, comm));
      importer_ = rcp(new Tpetra::Import<LO, GO>(A.getRowMap(), rootMap_));
      RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
      if (comm->getRank() == 0) serialMap_ = rcp(new Map(n, size_t(n), 0, self));
    }
    CrsMatrix root(rootMap_, 0);
    root.doImport(A, *importer_, Tpetra::INSERT);
    root.fillComplete(rootMap_, rootMap_);
    if (comm->getRank() != 0) return;
    std::vector<size_t> counts(n);
    for (size_t i = 0; i < n; ++i) counts[i] = root.getNumEntriesInGlobalRow(GO(i));
    auto S = rcp(new CrsMatrix(serialMap_, Teuchos::ArrayView<const size_t>(counts)));
    Teuchos::Array<GO> cols;
    Teuchos::Array<double> vals;
    for (size_t i = 0; i < n; ++i) {
      cols.resize(counts[i]);
      vals.resize(counts[i]);
      size_t got = 0;
      root.getGlobalRowCopy(GO(i), cols(), vals(), got);
      S->insertGlobalValues(GO(i), cols(0, got), vals(0, got));
    }
    S->fillComplete(serialMap_, serialMap_);
    rootSerial_ = S;
  }

  std::string package_;
  SerialFactorization serial_;
  RCP<const CrsMatrix> A_;
  RCP<const Map> rootMap_, serialMap_;
  RCP<Tpetra::Import<LO, GO>> importer_;
  RCP<const CrsMatrix> rootSerial_;
  double factorEntries_ = 0.0;
};

}  // namespace

std::unique_ptr<FactorizationBackend> makeAmesos2RootBackend(const std::string& package) {
  return std::make_unique<Amesos2RootBackend>(package);
}

bool amesos2Available(const std::string& package) { return Amesos2::query(package); }

std::vector<std::string> amesos2Packages() {
  std::vector<std::string> p = {"KLU2"};
  for (const char* other : {"Basker", "SuperLU", "Umfpack"})
    if (amesos2Available(other)) p.push_back(other);
  return p;
}

std::vector<std::string> directPackages() {
  std::vector<std::string> p = amesos2Packages();
  if (mumpsAvailable()) p.push_back("MUMPS");
  return p;
}

}  // namespace choc
