// The contact active set (contact/ContactActiveSet.hpp): restore returns to the last saved
// state and bumps the version only when a status changes; a checkpoint holds the saved state
// (not the trial one) and gives it back; a correction moves lambda by scale times the step.
#include <gtest/gtest.h>

#include "contact/ContactActiveSet.hpp"

namespace choc {
namespace {

TEST(ContactActiveSet, RestoreArchiveAndCorrection) {
  ContactActiveSet s;
  s.status = {1, 0, 1};
  s.lambda = {10.0, 0.0, 5.0};
  s.scale = 2.0;
  s.commit();
  EXPECT_EQ(s.activeCount(), 2);
  s.applyCorrection({1.0, 0.0, -0.5});
  EXPECT_EQ(s.lambda, (std::vector<double>{12.0, 0.0, 4.0}));
  s.revert();  // same statuses: no new version
  EXPECT_EQ(s.version, 0);
  EXPECT_EQ(s.lambda, (std::vector<double>{10.0, 0.0, 5.0}));
  s.status[1] = 1;
  s.lambda[1] = 3.0;
  StateArchive a;
  s.archive(a);  // the accepted state
  s.revert();
  EXPECT_EQ(s.version, 1);
  EXPECT_EQ(s.status, (std::vector<char>{1, 0, 1}));
  ContactActiveSet t;
  t.restore(a, 3);
  EXPECT_EQ(t.status, (std::vector<char>{1, 0, 1}));
  EXPECT_EQ(t.lambda, (std::vector<double>{10.0, 0.0, 5.0}));
  EXPECT_EQ(t.scale, 2.0);
}

}  // namespace
}  // namespace choc
