// The small utilities every module uses: printf formatting, "did you mean", name lists,
// 3-vectors.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "core/DidYouMean.hpp"
#include "core/Format.hpp"
#include "core/Vec3.hpp"

namespace choc {
namespace {

TEST(Format, ProducesPrintfTextOfAnyLength) {
  EXPECT_EQ(format("%d steps, %.3e s", 12, 1.5e-6), "12 steps, 1.500e-06 s");
  const std::string long_ = format("%s|%s", std::string(500, 'a').c_str(), std::string(700, 'b').c_str());
  EXPECT_EQ(long_.size(), 1201u);
  EXPECT_EQ(long_[500], '|');
  EXPECT_EQ(format("%s", ""), "");
}

TEST(Format, ShortNumberIsPercentG) {
  EXPECT_EQ(shortNumber(1e10), "1e+10");
  EXPECT_EQ(shortNumber(0.5), "0.5");
  EXPECT_EQ(shortNumber(INFINITY), "inf");
  EXPECT_EQ(shortNumber(-INFINITY), "-inf");
}

TEST(DidYouMean, SuggestsOnlyCloseNames) {
  const std::vector<std::string> names = {"Density", "Young's Modulus", "Poisson's Ratio"};
  EXPECT_EQ(closestName("Densty", names), "Density");
  EXPECT_EQ(closestName("density", names), "Density");  // case-insensitive
  EXPECT_EQ(didYouMean("Densty", names), "did you mean 'Density'? ");
  EXPECT_EQ(closestName("Temperature", names), "");
  EXPECT_EQ(didYouMean("Temperature", names), "");
  EXPECT_EQ(didYouMean("x", {}), "");
}

TEST(DidYouMean, NameLists) {
  EXPECT_EQ(joinNames({"A", "B", "C"}), "A, B, C");
  EXPECT_EQ(joinNames({}), "(none)");
  EXPECT_EQ(quotedNames({"Modal", "Transient"}), "'Modal', 'Transient'");
}

TEST(Vec3, DotCrossNorm) {
  const Vec3 x{1, 0, 0}, y{0, 1, 0};
  EXPECT_EQ(cross(x, y), (Vec3{0, 0, 1}));
  EXPECT_EQ(dot(x, y), 0.0);
  EXPECT_DOUBLE_EQ(norm(Vec3{3, 4, 12}), 13.0);
  EXPECT_EQ((Vec3{3, 4, 5} - Vec3{1, 1, 1}), (Vec3{2, 3, 4}));
}

}  // namespace
}  // namespace choc
