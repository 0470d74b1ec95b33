// The local frame of a shock obstacle: e1 along the obstacle axis n (NORM_OBST), e2 and e3
// span the plane in which the shock normal lies. Built as R = Rz(alpha) Ry(beta) Rx(gamma)
// with alpha, beta the azimuth and elevation of n and gamma a twist about n (ANGL_VRIL):
// n = x gives the global frame; n = y gives e2 = -x; n = z gives e3 = -x.
#pragma once
#include "core/Vec3.hpp"

namespace choc {

struct ObstacleFrame {
  Vec3 e1, e2, e3;
};

// Throws std::invalid_argument when the axis is zero.
ObstacleFrame obstacleFrame(const Vec3& axis, double twistRadians = 0.0);

}  // namespace choc
