// Node-to-face pairing on generated two-bar scenes: outward normals, reference gaps,
// bilinear weights on non-matching faces, tributary areas.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/ContactPairing.hpp"
#include "test_contact_helpers.hpp"

namespace choc {
namespace {

using test::barContactScene;

TEST(ContactPairing, MatchingFacesPairNodeToNode) {
  const Mesh m = barContactScene(1, 1, 1e-5);
  const PairingResult r = pairNodeToFace(m, {"ifc", "CNT_POU1", "CNT_POU2", 1e-3}, 0);
  ASSERT_EQ(r.projections.size(), 4u);
  EXPECT_TRUE(r.unpaired.empty());
  double area = 0;
  for (const auto& p : r.projections) {
    EXPECT_NEAR(p.normal[2], -1.0, 1e-14);  // bar 1's contact face looks towards -z
    EXPECT_NEAR(p.gap0, 1e-5, 1e-15);
    double wmax = 0;
    for (double w : p.weights) wmax = std::max(wmax, w);
    EXPECT_NEAR(wmax, 1.0, 1e-12);  // on a master node
    area += p.area;
  }
  EXPECT_NEAR(area, 4e-4, 1e-18);
}

TEST(ContactPairing, NonMatchingFacesUseBilinearWeights) {
  const Mesh m = barContactScene(1, 3, 2e-5);  // 16 slave nodes on one master face
  const PairingResult r = pairNodeToFace(m, {"ifc", "CNT_POU1", "CNT_POU2", 1e-3}, 0);
  ASSERT_EQ(r.projections.size(), 16u);
  // The projection lies straight above the slave node, at the gap.
  const double area = test::expectProjectionsAbove(m, r, 2e-5, {1e-14, 1e-12, 1e-15});
  EXPECT_NEAR(area, 4e-4, 1e-17);
}

TEST(ContactPairing, MissingSideSetIsNamed) {
  const Mesh m = barContactScene(1, 1, 1e-5);
  try {
    pairNodeToFace(m, {"ifc", "CNT_POU9", "CNT_POU2", 1e-3}, 0);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("CNT_POU9"), std::string::npos);
  }
  // Beyond the search distance nothing pairs.
  EXPECT_THROW(pairNodeToFace(m, {"ifc", "CNT_POU1", "CNT_POU2", 1e-6}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace choc
