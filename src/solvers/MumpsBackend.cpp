// The MUMPS backend (see FactorizationBackend.hpp): distributed assembled input (ICNTL(18) = 3),
// the analysis once per graph, the factorisation per matrix, a centralised right-hand side and
// solution on rank 0; symmetric matrices by LDL^T on their lower triangle. Errors are MUMPS' global ones (INFOG(1), the same on every rank): a
// workspace too small is retried with twice the relaxation (ICNTL(14)), up to 4 times.
#include "solvers/FactorizationBackend.hpp"

#ifdef CHOC_HAVE_MUMPS
#include <dmumps_c.h>
#include <mpi.h>

#include <Teuchos_DefaultMpiComm.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_MultiVector.hpp>

#include "core/Errors.hpp"
#include "core/Format.hpp"
#include "fem/SymmetricProduct.hpp"
#endif

namespace choc {

#ifdef CHOC_HAVE_MUMPS
namespace {

// One MUMPS instance: general (LU) or symmetric (LDL^T with pivoting, given the lower triangle).
class MumpsInstance {
 public:
  explicit MumpsInstance(bool symmetric) : symmetric_(symmetric) {}
  MumpsInstance(const MumpsInstance&) = delete;
  MumpsInstance& operator=(const MumpsInstance&) = delete;
  ~MumpsInstance() { finish(); }

  std::string factor(const RCP<const CrsMatrix>& A) {
    start(*A);
    const bool newGraph = A.get() != A_.get() || A->getNodeNumEntries() != entries_;
    A_ = A;
    load(*A, newGraph);
    if (newGraph || !analysed_) {
      analysed_ = false;
      if (std::string f = run(1, "analysis"); !f.empty()) return f;
      analysed_ = true;
    }
    std::string f;
    for (int retry = 0; retry <= 4; ++retry) {
      f = run(2, "factorisation");
      const int code = id_.infog[0];
      if (code != -8 && code != -9 && code != -14 && code != -15 && code != -17 && code != -20) break;
      id_.icntl[13] *= 2;  // ICNTL(14): the workspace's relaxation [%]
    }
    return f;
  }

  // INFOG(29): the factors' entries (negative: in millions).
  double factorEntries() const { return id_.infog[28] < 0 ? -1e6 * id_.infog[28] : double(id_.infog[28]); }

  // x = A^-1 b, the right-hand side gathered on rank 0 (MUMPS' centralised right-hand side).
  std::string solve(const MultiVector& b, MultiVector& x) {
    const auto comm = A_->getComm();
    const Tpetra::global_size_t n = A_->getGlobalNumRows();
    if (importerSource_.get() != A_->getRowMap().get()) {
      rootMap_ = rcp(new Map(n, comm->getRank() == 0 ? size_t(n) : 0, 0, comm));
      importer_ = rcp(new Tpetra::Import<LO, GO>(A_->getRowMap(), rootMap_));
      importerSource_ = A_->getRowMap();
    }
    // Every column in one solve phase (MUMPS blocks them: the factors are read once per block).
    MultiVector root(rootMap_, b.getNumVectors());
    root.doImport(b, *importer_, Tpetra::INSERT);
    auto data = root.get1dViewNonConst();
    id_.rhs = comm->getRank() == 0 ? data.getRawPtr() : nullptr;
    id_.nrhs = MUMPS_INT(b.getNumVectors());
    id_.lrhs = MUMPS_INT(n);
    const std::string f = run(3, "solve");
    id_.rhs = nullptr;
    if (!f.empty()) return f;
    x.doExport(root, *importer_, Tpetra::INSERT);
    return "";
  }

 private:
  void start(const CrsMatrix& A) {
    if (initialized_) return;
    auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(A.getComm(), true);
    id_.comm_fortran = MUMPS_INT(MPI_Comm_c2f(*mpi->getRawMpiComm()));
    id_.par = 1;                    // rank 0 works too
    id_.sym = symmetric_ ? 2 : 0;   // 2: symmetric, not necessarily definite (a saddle point)
    id_.job = -1;
    dmumps_c(&id_);
    if (id_.infog[0] < 0)
      throw NumericalError(format("MUMPS: initialisation failed (INFOG(1) = %d)", int(id_.infog[0])));
    initialized_ = true;
    id_.icntl[0] = -1;  // no messages: choc reports MUMPS' errors itself
    id_.icntl[1] = -1;
    id_.icntl[2] = -1;
    id_.icntl[3] = 0;
    id_.icntl[17] = 3;  // ICNTL(18): the matrix distributed by rows
    id_.icntl[6] = 7;   // ICNTL(7): the ordering MUMPS finds best (METIS, SCOTCH, PORD, AMD...)
  }

  void finish() {
    if (!initialized_) return;
    id_.job = -2;
    dmumps_c(&id_);
    initialized_ = false;
  }

  // The local rows of A as (row, column, value) triples, 1-based global indices (the lower
  // triangle of a symmetric matrix); the indices only when the graph is new.
  void load(const CrsMatrix& A, bool newGraph) {
    const auto L = A.getLocalMatrixHost();
    const auto rowMap = A.getRowMap(), colMap = A.getColMap();
    const size_t nRows = rowMap->getNodeNumElements();
    entries_ = A.getNodeNumEntries();
    if (newGraph) {
      irn_.clear();
      jcn_.clear();
      taken_.clear();
      for (size_t i = 0; i < nRows; ++i)
        for (size_t k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k) {
          const GO row = rowMap->getGlobalElement(LO(i)), col = colMap->getGlobalElement(L.graph.entries(k));
          if (symmetric_ && col > row) continue;
          irn_.push_back(MUMPS_INT(row + 1));
          jcn_.push_back(MUMPS_INT(col + 1));
          taken_.push_back(k);
        }
    }
    values_.resize(taken_.size());
    for (size_t e = 0; e < taken_.size(); ++e) values_[e] = L.values(taken_[e]);
    id_.n = MUMPS_INT(A.getGlobalNumRows());
    id_.nnz_loc = MUMPS_INT8(values_.size());
    id_.irn_loc = irn_.data();
    id_.jcn_loc = jcn_.data();
    id_.a_loc = values_.data();
  }

  // One MUMPS phase; the failure's message ("" on success), the same on every rank.
  std::string run(int job, const char* phase) {
    id_.job = job;
    dmumps_c(&id_);
    const int code = id_.infog[0];
    if (code >= 0) return "";
    const int detail = id_.infog[1];
    if (code == -10)
      return format("MUMPS %s: the matrix is numerically singular (INFOG(1) = -10)", phase);
    if (code == -13)
      throw OutOfMemory(format("MUMPS %s: an allocation of %d %s failed (INFOG(1) = -13); run on a machine "
                               "with more memory or more ranks", phase, detail < 0 ? -detail : detail,
                               detail < 0 ? "million bytes" : "bytes"));
    return format("MUMPS %s failed: INFOG(1) = %d, INFOG(2) = %d", phase, code, detail);
  }

  bool symmetric_;
  DMUMPS_STRUC_C id_{};
  bool initialized_ = false, analysed_ = false;
  RCP<const CrsMatrix> A_;
  size_t entries_ = 0;
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<size_t> taken_;  // the local entries given to MUMPS (all, or the lower triangle)
  std::vector<double> values_;
  RCP<const Map> rootMap_;
  RCP<Tpetra::Import<LO, GO>> importer_;
  RCP<const Map> importerSource_;  // the row map importer_ was built from
};

// A matrix the caller says is symmetric (the contact saddle point without friction or links)
// and that is symmetric within round-off in each rank's block (fem/SymmetricProduct's test, which
// does not see the other ranks' columns: hence the caller's word) is factored by the symmetric
// instance, LDL^T on its lower triangle (half the entries, about half the work); any other by
// the general one. Each keeps its own analysis of the graph.
class MumpsBackend : public FactorizationBackend {
 public:
  explicit MumpsBackend(bool symmetricHint) : symmetricHint_(symmetricHint) {}
  std::string factor(RCP<const CrsMatrix> A) override {
    const bool symmetric = symmetricHint_ && SymmetricProduct::build(*A) != nullptr;  // collective
    current_ = symmetric ? &symmetric_ : &general_;
    factored_ = true;
    return current_->factor(A);
  }
  std::string solve(const MultiVector& b, MultiVector& x) override { return current_->solve(b, x); }
  double factorEntries() const override { return factored_ ? current_->factorEntries() : 0.0; }
  // The oblique sphere (17,117 unknowns): about 280 columns in blocks for the time of 106 solves
  // of one right-hand side (the factors are read once per block).
  int columnsPerSolve() const override { return 2; }
  // "MUMPS", then the factorisation last made: "MUMPS (LU)" or "MUMPS (LDL^T)".
  std::string name() const override {
    if (!factored_) return "MUMPS";
    return current_ == &symmetric_ ? "MUMPS (LDL^T)" : "MUMPS (LU)";
  }

 private:
  bool symmetricHint_;
  bool factored_ = false;
  MumpsInstance general_{false}, symmetric_{true};
  MumpsInstance* current_ = &general_;
};

}  // namespace

std::unique_ptr<FactorizationBackend> makeMumpsBackend(bool symmetric) {
  return std::make_unique<MumpsBackend>(symmetric);
}
bool mumpsAvailable() { return true; }
#else
std::unique_ptr<FactorizationBackend> makeMumpsBackend(bool) { return nullptr; }
bool mumpsAvailable() { return false; }
#endif

}  // namespace choc
