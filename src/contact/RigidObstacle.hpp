// A rigid obstacle given by its geometry instead of a mesh: a plane, a sphere or a (infinite)
// cylinder, fixed or translating at a prescribed constant velocity. Contact pairs a slave
// side set with it (node to obstacle). The body is on the side the plane's normal points to,
// outside the sphere, outside the cylinder.
#pragma once
#include <string>

#include "core/Vec3.hpp"

namespace choc {

struct RigidObstacle {
  enum class Shape { Plane, Sphere, Cylinder };
  Shape shape = Shape::Plane;
  Vec3 point{0, 0, 0};     // plane: a point on it; sphere: the centre; cylinder: a point of the axis
  Vec3 direction{0, 0, 1}; // plane: the normal towards the body; cylinder: the axis (unit)
  double radius = 0.0;     // sphere, cylinder [m]
  Vec3 velocity{0, 0, 0};  // translation of the whole obstacle [m/s]
};

// Signed distance from the obstacle's surface (positive on the body's side) and the unit
// normal of the surface at the closest point, pointing towards the body, at time t.
struct ObstacleDistance {
  double gap = 0.0;
  Vec3 normal{0, 0, 1};
};

// Throws std::invalid_argument for a zero normal or axis or a non-positive radius (message
// without the parameter path); normalises the direction.
RigidObstacle validatedObstacle(RigidObstacle o);
// Throws std::invalid_argument when x lies on a sphere's centre or a cylinder's axis (the
// normal is undefined there).
ObstacleDistance distanceTo(const RigidObstacle& o, const Vec3& x, double t);
std::string shapeName(RigidObstacle::Shape s);

}  // namespace choc
