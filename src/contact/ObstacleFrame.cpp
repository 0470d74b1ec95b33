#include "contact/ObstacleFrame.hpp"

#include <cmath>
#include <stdexcept>

namespace choc {

ObstacleFrame obstacleFrame(const Vec3& axis, double gamma) {
  const double len = std::sqrt(dot(axis, axis));
  if (!(len > 0)) throw std::invalid_argument("obstacle axis must be a non-zero vector");
  const Vec3 n{axis[0] / len, axis[1] / len, axis[2] / len};
  const double alpha = std::atan2(n[1], n[0]);
  const double beta = -std::asin(std::max(-1.0, std::min(1.0, n[2])));
  const double ca = std::cos(alpha), sa = std::sin(alpha), cb = std::cos(beta), sb = std::sin(beta);
  const double cg = std::cos(gamma), sg = std::sin(gamma);
  // Columns of R = Rz(alpha) Ry(beta) Rx(gamma).
  const double R[3][3] = {
      {ca * cb, ca * sb * sg - sa * cg, ca * sb * cg + sa * sg},
      {sa * cb, sa * sb * sg + ca * cg, sa * sb * cg - ca * sg},
      {-sb, cb * sg, cb * cg},
  };
  ObstacleFrame f;
  for (int i = 0; i < 3; ++i) {
    f.e1[i] = R[i][0];
    f.e2[i] = R[i][1];
    f.e3[i] = R[i][2];
  }
  return f;
}

}  // namespace choc
