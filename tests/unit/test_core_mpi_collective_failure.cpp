// collectiveFailure: a failure seen by one rank reaches every rank, with its message.
#include <gtest/gtest.h>

#include <string>

#include <Teuchos_DefaultComm.hpp>

#include "core/CollectiveFailure.hpp"

namespace choc {
namespace {

TEST(MpiCollectiveFailure, NoFailureGivesEmptyOnEveryRank) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  EXPECT_EQ(collectiveFailure(*comm, ""), "");
}

TEST(MpiCollectiveFailure, TheLastRanksFailureReachesEveryRank) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  const int last = comm->getSize() - 1;
  const std::string mine = comm->getRank() == last ? "pivot " + std::to_string(last) + " is zero" : "";
  EXPECT_EQ(collectiveFailure(*comm, mine), "pivot " + std::to_string(last) + " is zero");
}

TEST(MpiCollectiveFailure, TheLowestFailingRankIsReported) {
  auto comm = Teuchos::DefaultComm<int>::getComm();
  EXPECT_EQ(collectiveFailure(*comm, "rank " + std::to_string(comm->getRank())), "rank 0");
}

}  // namespace
}  // namespace choc
