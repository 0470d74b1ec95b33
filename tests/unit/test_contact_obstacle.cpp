// Rigid obstacles: signed distance and normal of a plane, a sphere and a cylinder (moving or
// not) against their closed forms, the refusals of degenerate geometry, and the pairing of a
// slave side set with an obstacle.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "contact/ContactPairing.hpp"
#include "contact/RigidObstacle.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/MeshFile.hpp"

namespace choc {
namespace {

RigidObstacle obstacle(RigidObstacle::Shape shape, Vec3 point, Vec3 direction, double radius,
                       Vec3 velocity = {0, 0, 0}) {
  RigidObstacle o;
  o.shape = shape;
  o.point = point;
  o.direction = direction;
  o.radius = radius;
  o.velocity = velocity;
  return validatedObstacle(o);
}

TEST(RigidObstacle, PlaneDistanceIsAlongItsUnitNormalAndFollowsItsVelocity) {
  // Normal (3, 0, 4) normalised to (0.6, 0, 0.8); the plane moves at 2 m/s along x.
  const RigidObstacle p = obstacle(RigidObstacle::Shape::Plane, {1, 0, 0}, {3, 0, 4}, 0, {2, 0, 0});
  EXPECT_DOUBLE_EQ(p.direction[0], 0.6);
  const ObstacleDistance d0 = distanceTo(p, {1, 5, 1}, 0.0);
  EXPECT_NEAR(d0.gap, 0.8, 1e-15);
  EXPECT_NEAR(d0.normal[2], 0.8, 1e-15);
  // At t = 0.5 s the plane went 1 m along x: the gap shrinks by 0.6 * 1.
  EXPECT_NEAR(distanceTo(p, {1, 5, 1}, 0.5).gap, 0.2, 1e-15);
  EXPECT_LT(distanceTo(p, {0, 0, 0}, 0.0).gap, 0.0);  // behind the plane: penetration
}

TEST(RigidObstacle, SphereAndCylinderNormalsPointAwayFromTheirAxis) {
  const RigidObstacle s = obstacle(RigidObstacle::Shape::Sphere, {0, 0, 1}, {0, 0, 0}, 0.5);
  const ObstacleDistance ds = distanceTo(s, {0, 3, 5}, 0.0);  // |(0, 3, 4)| = 5
  EXPECT_NEAR(ds.gap, 4.5, 1e-14);
  EXPECT_NEAR(ds.normal[1], 0.6, 1e-15);
  EXPECT_NEAR(ds.normal[2], 0.8, 1e-15);
  const RigidObstacle c = obstacle(RigidObstacle::Shape::Cylinder, {0, 0, 0}, {0, 0, 2}, 1.0);
  const ObstacleDistance dc = distanceTo(c, {0.6, 0.8, 7}, 0.0);  // on the surface
  EXPECT_NEAR(dc.gap, 0.0, 1e-15);
  EXPECT_NEAR(dc.normal[0], 0.6, 1e-15);
  EXPECT_NEAR(dc.normal[2], 0.0, 1e-15);  // no component along the axis
  EXPECT_NEAR(distanceTo(c, {0.3, 0.4, -2}, 0.0).gap, -0.5, 1e-15);  // inside: penetration
}

TEST(RigidObstacle, DegenerateGeometryIsRefused) {
  EXPECT_THROW(obstacle(RigidObstacle::Shape::Plane, {0, 0, 0}, {0, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(obstacle(RigidObstacle::Shape::Cylinder, {0, 0, 0}, {0, 0, 0}, 1), std::invalid_argument);
  EXPECT_THROW(obstacle(RigidObstacle::Shape::Sphere, {0, 0, 0}, {0, 0, 1}, 0), std::invalid_argument);
  EXPECT_THROW(obstacle(RigidObstacle::Shape::Cylinder, {0, 0, 0}, {0, 0, 1}, -1), std::invalid_argument);
  const RigidObstacle s = obstacle(RigidObstacle::Shape::Sphere, {1, 1, 1}, {0, 0, 1}, 1);
  EXPECT_THROW(distanceTo(s, {1, 1, 1}, 0.0), std::invalid_argument);  // at the centre
}

TEST(RigidObstacle, EverySlaveNodePairsWithItsAreaAndGap) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  o.along1 = o.along2 = 2;
  o.across1 = o.across2 = 2;
  o.gap = 1e-5;
  const Mesh m = generateBarImpactMesh(o);
  PairDefinition def{"wall", "", "CNT_POU2", 1e-3};
  def.hasObstacle = true;
  def.obstacle = obstacle(RigidObstacle::Shape::Plane, {0, 0, 0.25}, {0, 0, -1}, 0);
  const PairingResult r = pairNodeToObstacle(m, def, 3);
  ASSERT_EQ(r.projections.size(), 9u);  // 3 x 3 nodes of bar 2's face at z = 0
  double area = 0;
  for (const auto& p : r.projections) {
    EXPECT_EQ(p.pair, 3);
    EXPECT_TRUE(p.masterNodes.empty());
    EXPECT_NEAR(p.gap0, 0.25, 1e-15);  // the plane z = 0.25 faces down towards the face
    EXPECT_NEAR(p.normal[2], -1.0, 1e-15);
    area += p.area;
  }
  EXPECT_NEAR(area, 4e-4, 1e-18);
}

// The slave areas of LINE3 edges: per unit thickness in plane strain, whole rings when
// axisymmetric. meshes/sdnl111_2d_quad8.msh's edge CNT_POU2 runs from x = 0 to 0.02 at y = 0:
// 0.02 m^2 per metre of thickness, pi 0.02^2 as a disc of radius 0.02 m.
TEST(RigidObstacle, SlaveAreasOfEdgesArePerUnitThicknessOrWholeRings) {
  const Mesh m = readMeshFile(std::string(CHOC_SOURCE_DIR) + "/meshes/sdnl111_2d_quad8.msh");
  PairDefinition def{"wall", "", "CNT_POU2", 1e-3};
  def.hasObstacle = true;
  def.obstacle = obstacle(RigidObstacle::Shape::Plane, {0, 1, 0}, {0, -1, 0}, 0);
  for (bool axisymmetric : {false, true}) {
    def.axisymmetric = axisymmetric;
    const PairingResult r = pairNodeToObstacle(m, def, 0);
    ASSERT_EQ(r.projections.size(), 3u);  // one LINE3 edge
    double area = 0;
    for (const auto& p : r.projections) {
      EXPECT_GT(p.area, 0.0);
      area += p.area;
    }
    EXPECT_NEAR(area, axisymmetric ? M_PI * 4e-4 : 0.02, 1e-15) << axisymmetric;
  }
}

}  // namespace
}  // namespace choc
