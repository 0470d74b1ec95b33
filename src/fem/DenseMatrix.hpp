// A small dense row-major matrix for element computations.
#pragma once
#include <cassert>
#include <cstddef>
#include <vector>

namespace choc {

class DenseMatrix {
 public:
  DenseMatrix() = default;
  DenseMatrix(int rows, int cols) : rows_(rows), cols_(cols), a_(std::size_t(rows) * cols, 0.0) {}
  void resize(int rows, int cols) {
    rows_ = rows;
    cols_ = cols;
    a_.assign(std::size_t(rows) * cols, 0.0);
  }
  int rows() const { return rows_; }
  int cols() const { return cols_; }
  double& operator()(int i, int j) {
    assert(i >= 0 && i < rows_ && j >= 0 && j < cols_);
    return a_[std::size_t(i) * cols_ + j];
  }
  double operator()(int i, int j) const {
    assert(i >= 0 && i < rows_ && j >= 0 && j < cols_);
    return a_[std::size_t(i) * cols_ + j];
  }
  double* data() { return a_.data(); }
  const double* data() const { return a_.data(); }

 private:
  int rows_ = 0, cols_ = 0;
  std::vector<double> a_;
};

}  // namespace choc
