// A small square sparse matrix that every rank holds whole (the same entries on each), factored
// by each rank alone: Amesos2 KLU2 on MPI_COMM_SELF (sparse LU with partial pivoting and a
// fill-reducing ordering; Debian's KLU2 is right on one rank, see Amesos2RootBackend.cpp). For
// the Gram matrices of many active contact constraints (contact/ContactProjection.hpp), whose
// dense factors grow as m^2 in memory and m^3 in time.
#pragma once
#include <memory>
#include <vector>

namespace choc {

class ReplicatedSparseLU {
 public:
  struct Entry {
    int row, col;
    double value;  // entries named twice are summed
  };
  ReplicatedSparseLU();
  ~ReplicatedSparseLU();
  ReplicatedSparseLU(const ReplicatedSparseLU&) = delete;
  ReplicatedSparseLU& operator=(const ReplicatedSparseLU&) = delete;
  // Factors the m x m matrix of the entries. Returns false when it is singular or so nearly
  // singular that A x = A 1 is not solved to 1e-6 (a linearly dependent row).
  bool factor(int m, const std::vector<Entry>& entries);
  // y = A^-1 y.
  void solve(std::vector<double>& y) const;
  int size() const { return m_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  int m_ = 0;
};

}  // namespace choc
