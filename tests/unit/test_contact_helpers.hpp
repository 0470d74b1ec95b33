// Helpers of the contact tests: the two-bar scene, the master point of a projection and the
// check that projections lie straight above their slave nodes.
#pragma once
#include <gtest/gtest.h>

#include "contact/ContactPairing.hpp"
#include "mesh/BarImpactMesh.hpp"

namespace choc::test {

// Two HEX8 bars along z (2 elements each), across1 x across1 and across2 x across2 elements in
// their 0.02 x 0.02 sections, bar 1's contact face CNT_POU1 `gap` above bar 2's CNT_POU2.
inline Mesh barContactScene(int across1, int across2, double gap) {
  BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'z';
  o.along1 = o.along2 = 2;
  o.across1 = across1;
  o.across2 = across2;
  o.gap = gap;
  return generateBarImpactMesh(o);
}

// sum_i w_i x_i over the projection's master nodes; `sum` receives sum_i w_i.
inline Point3 masterPoint(const Mesh& m, const SlaveProjection& p, double& sum) {
  sum = 0;
  Point3 x{};
  for (size_t i = 0; i < p.weights.size(); ++i) {
    sum += p.weights[i];
    for (int d = 0; d < 3; ++d) x[d] += p.weights[i] * m.coords[p.masterNodes[i]][d];
  }
  return x;
}

// Tolerances of expectProjectionsAbove: on sum_i w_i - 1, on the master point's x and y
// against the slave node's, and on the initial gap.
struct ProjectionTolerances {
  double weights = 0, lateral = 0, gap = 0;
};

// Every projection of two parallel faces `gap` apart along z: weights summing to 1, the master
// point straight above (or below) its slave node, the initial gap; returns the summed areas.
inline double expectProjectionsAbove(const Mesh& m, const PairingResult& r, double gap,
                                     const ProjectionTolerances& tol) {
  double area = 0;
  for (const auto& p : r.projections) {
    double sum = 0;
    const Point3 x = masterPoint(m, p, sum);
    EXPECT_NEAR(sum, 1.0, tol.weights);
    EXPECT_NEAR(x[0], m.coords[p.slaveNode][0], tol.lateral);
    EXPECT_NEAR(x[1], m.coords[p.slaveNode][1], tol.lateral);
    EXPECT_NEAR(p.gap0, gap, tol.gap);
    area += p.area;
  }
  return area;
}

}  // namespace choc::test
