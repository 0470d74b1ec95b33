// Row-sum and HRZ (diagonal scaling) lumping of a scalar consistent mass matrix.
#include "fem/MassLumping.hpp"

namespace choc {

std::vector<double> rowSumLumping(const DenseMatrix& m) {
  std::vector<double> l(m.rows(), 0.0);
  for (int a = 0; a < m.rows(); ++a)
    for (int b = 0; b < m.cols(); ++b) l[a] += m(a, b);
  return l;
}

std::vector<double> hrzLumping(const DenseMatrix& m) {
  double total = 0.0, diagonal = 0.0;
  for (int a = 0; a < m.rows(); ++a) {
    diagonal += m(a, a);
    for (int b = 0; b < m.cols(); ++b) total += m(a, b);
  }
  std::vector<double> l(m.rows(), 0.0);
  if (diagonal == 0.0) return l;
  for (int a = 0; a < m.rows(); ++a) l[a] = m(a, a) * total / diagonal;
  return l;
}

}  // namespace choc
