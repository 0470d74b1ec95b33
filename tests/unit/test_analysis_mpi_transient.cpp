// The SDNL111 C benchmark (Lagrange contact, full HHT) gives the same history on every rank
// count: the run on the default communicator (2 ranks under ctest) against the same run on
// MPI_COMM_SELF made by rank 0 inside the test.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/DirectTransient.hpp"
#include "test_analysis_contact_helpers.hpp"

namespace choc {
namespace {

TEST(MpiTransient, Sdnl111cIsIdenticalOnOneAndSeveralRanks) {
  auto world = Tpetra::getDefaultComm();
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const std::string base = std::string(CHOC_BINARY_DIR) + "/test-scratch/mpi_transient";
  const HistoryTable par = test::runSdnl111cC2(base + "/np" + std::to_string(world->getSize()), "", world);
  // The serial reference on rank 0 (files are written by the world's rank 0 only).
  if (world->getRank() != 0) return;
  const HistoryTable ser = test::runSdnl111cC2(base + "/self", "", self);
  ASSERT_EQ(par.rows.size(), ser.rows.size());
  for (const char* col : {"N1:DZ", "N1:VZ", "interface:force", "energy:total"}) {
    const auto a = par.column(col), b = ser.column(col);
    double scale = 0, diff = 0;
    for (size_t i = 0; i < a.size(); ++i) {
      scale = std::max(scale, std::abs(b[i]));
      diff = std::max(diff, std::abs(a[i] - b[i]));
    }
    // Solver tolerance (direct solves: round-off, amplified over 400 steps).
    EXPECT_LE(diff, 1e-9 * scale) << col;
  }
}

}  // namespace
}  // namespace choc
