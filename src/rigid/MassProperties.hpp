// The mass, centre of mass and inertia tensor of a rigid body, summed from its elements (at
// their mass quadrature, exact for elements whose map is affine) and point masses, on each
// rank and then over the ranks: the sums are taken about a reference point (any point of the
// body, the same on every rank) so that a body far from the origin keeps its digits.
#pragma once
#include <vector>

#include "fem/Kinematics.hpp"
#include "fem/ShapeFunctions.hpp"
#include "rigid/Rotation.hpp"

namespace choc {

struct MassProperties {
  double mass = 0.0;
  Vec3 centre{};
  Matrix33 inertia{};       // about the centre, in the global axes
  Vec3 moments{};       // principal moments, ascending
  Matrix33 axes{};          // their axes (columns): inertia = axes diag(moments) axes^T
};

class MassPropertiesSum {
 public:
  explicit MassPropertiesSum(const Vec3& reference) : reference_(reference) {}
  // An element of the body (3D, or 2D per unit thickness; axisymmetric adds 2 pi r: its mass
  // only is meaningful). Throws std::invalid_argument for an inverted element.
  void addElement(SolidShape t, Kinematics k, const std::vector<Vec3>& x, double density);
  void addPoint(const Vec3& x, double mass);
  // The sums in one array (mass, first moments, second moments) for a reduction over the
  // ranks, and back.
  std::vector<double> sums() const;
  void setSums(const std::vector<double>& s);
  // The body's properties (mass > 0 required: throws std::invalid_argument otherwise).
  MassProperties properties() const;

 private:
  void add(const Vec3& x, double m);
  Vec3 reference_;
  double mass_ = 0.0;
  Vec3 first_{};                 // sum m (x - reference)
  std::array<double, 6> second_{};  // sum m (x - reference)_i (x - reference)_j, i <= j
};

}  // namespace choc
