// The MUMPS backend (see FactorizationBackend.hpp): distributed assembled input (ICNTL(18) = 3),
// the analysis once per graph, the factorisation per matrix, a centralised right-hand side and
// solution on rank 0. Errors are MUMPS' global ones (INFOG(1), the same on every rank): a
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
#endif

namespace choc {

#ifdef CHOC_HAVE_MUMPS
namespace {

class MumpsBackend : public FactorizationBackend {
 public:
  MumpsBackend() = default;
  MumpsBackend(const MumpsBackend&) = delete;
  MumpsBackend& operator=(const MumpsBackend&) = delete;
  ~MumpsBackend() override { finish(); }

  std::string factor(RCP<const CrsMatrix> A) override {
    start(*A);
    const bool newGraph = A.get() != A_.get() || A->getNodeNumEntries() != values_.size();
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

  std::string solve(const MultiVector& b, MultiVector& x) override {
    const auto comm = A_->getComm();
    const Tpetra::global_size_t n = A_->getGlobalNumRows();
    if (importerSource_.get() != A_->getRowMap().get()) {  // the right-hand side gathered on rank 0
      rootMap_ = rcp(new Map(n, comm->getRank() == 0 ? size_t(n) : 0, 0, comm));
      importer_ = rcp(new Tpetra::Import<LO, GO>(A_->getRowMap(), rootMap_));
      importerSource_ = A_->getRowMap();
    }
    MultiVector root(rootMap_, 1);
    for (size_t j = 0; j < b.getNumVectors(); ++j) {
      root.doImport(*b.getVector(j), *importer_, Tpetra::INSERT);
      auto data = root.getDataNonConst(0);
      id_.rhs = comm->getRank() == 0 ? data.getRawPtr() : nullptr;
      id_.nrhs = 1;
      id_.lrhs = MUMPS_INT(n);
      const std::string f = run(3, "solve");
      id_.rhs = nullptr;
      if (!f.empty()) return f;
      x.getVectorNonConst(j)->doExport(root, *importer_, Tpetra::INSERT);
    }
    return "";
  }

  std::string name() const override { return "MUMPS"; }

 private:
  void start(const CrsMatrix& A) {
    if (initialized_) return;
    auto mpi = Teuchos::rcp_dynamic_cast<const Teuchos::MpiComm<int>>(A.getComm(), true);
    id_.comm_fortran = MUMPS_INT(MPI_Comm_c2f(*mpi->getRawMpiComm()));
    id_.par = 1;  // rank 0 works too
    id_.sym = 0;  // general: friction's tangent is not symmetric
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

  // The local rows of A as (row, column, value) triples, 1-based global indices; the
  // indices only when the graph is new.
  void load(const CrsMatrix& A, bool newGraph) {
    const auto L = A.getLocalMatrixHost();
    const auto rowMap = A.getRowMap(), colMap = A.getColMap();
    const size_t nRows = rowMap->getNodeNumElements(), nnz = L.values.extent(0);
    if (newGraph) {
      irn_.resize(nnz);
      jcn_.resize(nnz);
      for (size_t i = 0; i < nRows; ++i)
        for (size_t k = L.graph.row_map(i); k < L.graph.row_map(i + 1); ++k) {
          irn_[k] = MUMPS_INT(rowMap->getGlobalElement(LO(i)) + 1);
          jcn_[k] = MUMPS_INT(colMap->getGlobalElement(L.graph.entries(k)) + 1);
        }
    }
    values_.assign(L.values.data(), L.values.data() + nnz);
    id_.n = MUMPS_INT(A.getGlobalNumRows());
    id_.nnz_loc = MUMPS_INT8(nnz);
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

  DMUMPS_STRUC_C id_{};
  bool initialized_ = false, analysed_ = false;
  RCP<const CrsMatrix> A_;
  std::vector<MUMPS_INT> irn_, jcn_;
  std::vector<double> values_;
  RCP<const Map> rootMap_;
  RCP<Tpetra::Import<LO, GO>> importer_;
  RCP<const Map> importerSource_;  // the row map importer_ was built from
};

}  // namespace

std::unique_ptr<FactorizationBackend> makeMumpsBackend() { return std::make_unique<MumpsBackend>(); }
bool mumpsAvailable() { return true; }
#else
std::unique_ptr<FactorizationBackend> makeMumpsBackend() { return nullptr; }
bool mumpsAvailable() { return false; }
#endif

}  // namespace choc
