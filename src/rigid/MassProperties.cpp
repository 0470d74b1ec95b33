#include "rigid/MassProperties.hpp"

#include <stdexcept>

#include "fem/SolidGeometry.hpp"

namespace choc {

namespace {
constexpr int kPair[6][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 1}, {1, 2}, {2, 2}};
}

void MassPropertiesSum::add(const Vec3& x, double m) {
  const Vec3 r = x - reference_;
  mass_ += m;
  for (int i = 0; i < 3; ++i) first_[i] += m * r[i];
  for (int p = 0; p < 6; ++p) second_[p] += m * r[kPair[p][0]] * r[kPair[p][1]];
}

void MassPropertiesSum::addElement(SolidShape t, Kinematics k, const std::vector<Vec3>& x, double density) {
  const QuadratureRule& rule = massRule(t);
  IsoparametricPoint p;
  for (int q = 0; q < int(rule.weights.size()); ++q) {
    const double w = solidVolumeWeight(t, k, x, rule, q, p);
    add(p.x, density * w);
  }
}

void MassPropertiesSum::addPoint(const Vec3& x, double mass) { add(x, mass); }

std::vector<double> MassPropertiesSum::sums() const {
  std::vector<double> s = {mass_, first_[0], first_[1], first_[2]};
  s.insert(s.end(), second_.begin(), second_.end());
  return s;
}

void MassPropertiesSum::setSums(const std::vector<double>& s) {
  if (s.size() != 10) throw std::invalid_argument("MassPropertiesSum::setSums: 10 sums expected");
  mass_ = s[0];
  for (int i = 0; i < 3; ++i) first_[i] = s[1 + i];
  for (int p = 0; p < 6; ++p) second_[p] = s[4 + p];
}

// About the centre c = reference + first / m: S_c = S - m d d^T (d = c - reference), and the
// inertia tensor I = tr(S_c) 1 - S_c.
MassProperties MassPropertiesSum::properties() const {
  if (!(mass_ > 0.0)) throw std::invalid_argument("a rigid body with no mass (its elements' density is zero?)");
  MassProperties out;
  out.mass = mass_;
  const Vec3 d = {first_[0] / mass_, first_[1] / mass_, first_[2] / mass_};
  out.centre = {reference_[0] + d[0], reference_[1] + d[1], reference_[2] + d[2]};
  Matrix33 S{};
  for (int p = 0; p < 6; ++p) {
    const int i = kPair[p][0], j = kPair[p][1];
    S[3 * i + j] = S[3 * j + i] = second_[p] - mass_ * d[i] * d[j];
  }
  const double trace = S[0] + S[4] + S[8];
  for (int k = 0; k < 9; ++k) out.inertia[k] = (k % 4 == 0 ? trace : 0.0) - S[k];
  const Eigen33 e = eigenOfSymmetric33(out.inertia);
  out.moments = e.values;
  out.axes = e.vectors;
  return out;
}

}  // namespace choc
