// The factorisation key (solvers/FactorizationKey.hpp): nothing valid means a new matrix; a
// change of coefficients or of the tangent's version means a new matrix; a change of the
// status alone is reported as such (the solver may keep its factorisation); forget() drops it.
#include <gtest/gtest.h>

#include "solvers/FactorizationKey.hpp"

namespace choc {
namespace {

FactorizationKey key(double cd, long long tangent, std::vector<char> status) {
  FactorizationKey k;
  k.coefficients = {4e6, 2e3, cd};
  k.tangent = tangent;
  k.status = std::move(status);
  return k;
}

TEST(FactorizationKey, EachChangeIsClassified) {
  FactorizationCache c;
  EXPECT_EQ(c.compare(key(1, 0, {1, 0})), KeyChange::Matrix);  // nothing factored yet
  c.record(key(1, 0, {1, 0}));
  EXPECT_TRUE(c.valid());
  EXPECT_EQ(c.compare(key(1, 0, {1, 0})), KeyChange::None);
  EXPECT_EQ(c.compare(key(1, 0, {1, 1})), KeyChange::StatusOnly);
  EXPECT_EQ(c.compare(key(0.5, 0, {1, 0})), KeyChange::Matrix);  // another step length
  EXPECT_EQ(c.compare(key(1, 1, {1, 0})), KeyChange::Matrix);    // the tangent changed
  EXPECT_EQ(c.compare(key(1, 1, {1, 1})), KeyChange::Matrix);
  c.forget();
  EXPECT_FALSE(c.valid());
  EXPECT_EQ(c.compare(key(1, 0, {1, 0})), KeyChange::Matrix);
}

}  // namespace
}  // namespace choc
