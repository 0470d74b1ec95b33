// Algebraic multigrid for elasticity, the preconditioner 'Multigrid': MueLu smoothed
// aggregation on the unknowns regrouped node by node (fem/NodalBlocks: block size = the
// components per node, the rigid-body modes from the nodal coordinates as the near-null
// space), Chebyshev smoothing. The Krylov method sees an operator on the system's own map:
// a residual is copied into the node-by-node rows (zero on fixed components, whose rows are
// decoupled and diagonal), one V-cycle is applied, and the free rows are copied back; the
// preconditioner is therefore symmetric positive definite when the system is, as CG needs.
//
// The hierarchy is kept for as long as its matrix: the analysis sets a new one only when the
// Newton matrix changes (its time-step coefficients, a change of contact status;
// solvers/FactorizationKey.hpp), and each new matrix gets a new hierarchy; the node-by-node
// matrix's graph is kept while A's graph is. (MueLu's reuse of a hierarchy's aggregates for the
// next matrix, its reuse types tP, RP and S, failed on the second matrix in Debian's Trilinos
// 13.2: Tpetra's matrix-matrix product refused the kept pattern; docs/performance/multigrid.md.)
//
// Aggregation needs elements of moderate aspect ratio: on bars of cubic HEX8 CG takes 28
// iterations at a stiffness-to-mass ratio of 1e5, on HEX8 five times longer than wide 116.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"
#include "fem/NodalBlocks.hpp"

namespace choc {

class ElasticityMultigrid : public Operator {
 public:
  explicit ElasticityMultigrid(std::shared_ptr<const NodalBlocks> blocks);
  ~ElasticityMultigrid() override;
  // The hierarchy for A. Throws NumericalError on failure.
  void compute(const RCP<const CrsMatrix>& A);

  RCP<const Map> getDomainMap() const override { return map_; }
  RCP<const Map> getRangeMap() const override { return map_; }
  void apply(const MultiVector& X, MultiVector& Y, Teuchos::ETransp mode = Teuchos::NO_TRANS,
             double alpha = 1.0, double beta = 0.0) const override;

  int levels() const;
  int builds() const { return builds_; }
  std::string description() const;

 private:
  struct Hierarchy;
  void buildBlockMatrix(const CrsMatrix& A);
  void refillBlockMatrix(const CrsMatrix& A);

  std::shared_ptr<const NodalBlocks> blocks_;
  RCP<const Map> map_;                 // the system's row map
  RCP<const Map> blockMap_;            // node-by-node rows
  RCP<CrsMatrix> blockA_;
  const void* graph_ = nullptr;        // the graph blockA_ was built for
  std::vector<LO> blockRowOfRow_;      // system row (local) -> block row (local)
  std::vector<LO> blockColOfEntry_;    // each entry of A's local rows -> block column (local)
  std::vector<LO> fixedRows_;          // local block rows of fixed components
  std::unique_ptr<Hierarchy> hierarchy_;
  mutable RCP<MultiVector> bx_, by_;
  int builds_ = 0;
};

}  // namespace choc
