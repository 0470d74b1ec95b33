// y = K x with a symmetric K stored once per pair of entries: the diagonal and the upper
// triangle of the block of rows and columns a rank owns (each stored entry a_ij, i < j, used
// twice: y_i += a_ij x_j and y_j += a_ij x_i), plus the entries in the columns of other ranks'
// unknowns as they are. A product streams about half the bytes of the CRS matrix (8 + 4 bytes
// per stored entry), which is what bounds it on a machine whose cores share the memory bus.
// Measured on the 300k-unknown explicit scene (docs/performance/explicit.md): a
// sub-step 10 to 6.8 ms on one rank, 6.2 to 3.8 ms on two (np = 2 speed-up 1.45 to 1.78).
//
// build() returns null when K is not symmetric within round-off (|a_ij - a_ji| at most 1e-12
// of the largest entry of row i, the entries compared in the rank's owned block; an entry
// without its transposed partner is not symmetric): the caller keeps Tpetra's product then.
// The product sums each row in another order than K's CRS product, so the two differ by
// round-off (Higham's bound for a sum of n terms).
#pragma once
#include <memory>
#include <vector>

#include <Tpetra_Import_decl.hpp>

#include "core/TpetraTypes.hpp"

namespace choc {

class SymmetricProduct {
 public:
  // Below this many rows K (81 entries per row on HEX8 meshes: 19 MB here) lies mostly in the
  // caches and the symmetric product gains less than 15 % (measured); the small inputs, the
  // reference decks among them, keep the CRS product's bits.
  static constexpr long long kWorthwhileRows = 20000;

  static std::unique_ptr<SymmetricProduct> build(const CrsMatrix& K);
  // K's values again, K having the graph of the matrix built from (its values changed: a new
  // effective matrix, a change of contact status): one pass over K, no allocation. Collective;
  // false on every rank when K is not symmetric within round-off or its graph is not the one
  // built from (the product is then not K's: build again or use K's own).
  bool refill(const CrsMatrix& K);

  // out = K x (x and out on K's row map, which must be its domain and range map).
  void apply(const Vector& x, Vector& out) const;

  size_t storedEntries() const { return upperCols_.size() + ghostCols_.size() + diag_.size(); }

 private:
  SymmetricProduct() = default;
  bool fill(const CrsMatrix& K, bool structure);
  bool matchesTranspose(size_t i, size_t j, double a, double scale, std::vector<size_t>& next) const;
  template <class LocalMatrix>
  bool fillRows(const LocalMatrix& A, bool structure, std::vector<size_t>& next);
  std::vector<LO> owned_;  // column map index -> owned row index, -1 for another rank's unknown
  bool identity_ = false;  // sorted rows, column c < rows is row c, the other ranks' columns after
  size_t entries_ = 0;     // K's local entries when built
  std::vector<double> diag_;
  std::vector<size_t> upperRows_;  // CSR of the upper triangle (column: owned row index)
  std::vector<LO> upperCols_;
  std::vector<double> upperVals_;
  std::vector<size_t> ghostRows_;  // CSR of the entries in other ranks' columns (column map index)
  std::vector<LO> ghostCols_;
  std::vector<double> ghostVals_;
  RCP<const Map> colMap_;                       // K's column map when built
  RCP<const Tpetra::Import<LO, GO>> importer_;  // K's; null on one rank
  mutable RCP<Vector> column_;                  // x on K's column map (ghost values)
};

}  // namespace choc
