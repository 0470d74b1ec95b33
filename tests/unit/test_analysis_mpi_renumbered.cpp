// SDNL111 C (Lagrange contact, full HHT) on its HEX8 mesh and on the same mesh with the nodes
// randomly renumbered: the same histories to solver tolerance (run by ctest on 1 and on 2
// ranks; with the 2-rank run of test_analysis_mpi_transient.cpp against the serial one, the
// histories do not depend on the numbering nor on the number of ranks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "analysis/DirectTransient.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "mesh/ExodusReader.hpp"
#include "test_analysis_contact_helpers.hpp"
#include "test_mesh_helpers.hpp"

namespace choc {
namespace {

TEST(MpiRenumbered, Sdnl111cDoesNotDependOnTheNodeNumbering) {
  auto comm = Tpetra::getDefaultComm();
  const std::string base = std::string(CHOC_BINARY_DIR) + "/test-scratch/renumbered/np" +
                           std::to_string(comm->getSize());
  std::filesystem::create_directories(base);
  const std::string original = std::string(CHOC_SOURCE_DIR) + "/meshes/sdnl111_3d.exo";
  const std::string shuffled = base + "/sdnl111_3d_renumbered.exo";
  if (comm->getRank() == 0) writeExodusMesh(renumberedMesh(readExodusMesh(original), 2026), shuffled);
  comm->barrier();
  const HistoryTable a = test::runSdnl111cC2(base + "/original", original, comm);
  const HistoryTable b = test::runSdnl111cC2(base + "/renumbered", shuffled, comm);
  if (comm->getRank() != 0) return;
  ASSERT_EQ(a.rows.size(), b.rows.size());
  ASSERT_GT(a.rows.size(), 100u);
  for (const char* col : {"N1:DZ", "N1:VZ", "interface:force", "energy:total"}) {
    const auto x = a.column(col), y = b.column(col);
    double scale = 0, diff = 0;
    for (size_t i = 0; i < x.size(); ++i) {
      scale = std::max(scale, std::abs(x[i]));
      diff = std::max(diff, std::abs(x[i] - y[i]));
    }
    ASSERT_GT(scale, 0) << col;
    // Direct solves of the same system in another order: round-off, amplified over 400 steps
    // (the bound of the rank-count test beside this one).
    EXPECT_LE(diff, 1e-9 * scale) << col;
  }
}

}  // namespace
}  // namespace choc
