#include "contact/RigidObstacle.hpp"

#include <stdexcept>

namespace choc {

namespace {

Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 plus(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }

// Unit vector along d; throws when d is (numerically) zero relative to the scale.
Vec3 unit(const Vec3& d, double scale, const char* what) {
  const double n = norm(d);
  if (!(n > 1e-12 * scale)) throw std::invalid_argument(what);
  return scaled(d, 1.0 / n);
}

}  // namespace

std::string shapeName(RigidObstacle::Shape s) {
  switch (s) {
    case RigidObstacle::Shape::Plane: return "plane";
    case RigidObstacle::Shape::Sphere: return "sphere";
    case RigidObstacle::Shape::Cylinder: return "cylinder";
  }
  return "?";
}

RigidObstacle validatedObstacle(RigidObstacle o) {
  if (o.shape != RigidObstacle::Shape::Sphere)
    o.direction = unit(o.direction, 1.0, o.shape == RigidObstacle::Shape::Plane
                                             ? "the plane's normal is zero"
                                             : "the cylinder's axis is zero");
  if (o.shape != RigidObstacle::Shape::Plane && !(o.radius > 0))
    throw std::invalid_argument("the " + shapeName(o.shape) + "'s radius must be > 0");
  return o;
}

ObstacleDistance distanceTo(const RigidObstacle& o, const Vec3& x, double t) {
  const Vec3 rel = x - plus(o.point, scaled(o.velocity, t));
  ObstacleDistance d;
  switch (o.shape) {
    case RigidObstacle::Shape::Plane:
      d.normal = o.direction;
      d.gap = dot(rel, o.direction);
      return d;
    case RigidObstacle::Shape::Sphere:
      d.normal = unit(rel, o.radius, "a slave node lies at the sphere's centre");
      d.gap = norm(rel) - o.radius;
      return d;
    case RigidObstacle::Shape::Cylinder: {
      const Vec3 radial = rel - scaled(o.direction, dot(rel, o.direction));
      d.normal = unit(radial, o.radius, "a slave node lies on the cylinder's axis");
      d.gap = norm(radial) - o.radius;
      return d;
    }
  }
  return d;
}

}  // namespace choc
