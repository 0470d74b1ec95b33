// The SDNL111 C benchmark (Lagrange contact, full HHT) gives the same history on every rank
// count: the run on the default communicator (2 ranks under ctest) against the same run on
// MPI_COMM_SELF made by rank 0 inside the test.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/ImplicitTransient.hpp"
#include "test_analysis_contact_helpers.hpp"

namespace choc {
namespace {

HistoryTable runC2(const std::string& dir, RCP<const Comm> comm) {
  std::filesystem::create_directories(dir);
  const std::string file = std::string(CHOC_SOURCE_DIR) + "/input/sdnl111c.xml";
  auto input = readXmlParameters(file);
  validate(*input, topLevelParameters(), InputLocation{file, ""});
  auto& an = input->sublist("Analyses");
  an.remove("c1_modified");
  an.sublist("c2_hht").set("End Time", 4e-4);
  an.sublist("c2_hht").set("Exodus Interval", 0);
  an.sublist("c2_hht").remove("Checks");  // the document's rows and the exact solution
  validateAnalyses(an, file);
  Model model(*input, file, comm);
  auto analyses = createAnalyses(an, file);
  setupAnalyses(analyses, model);
  RunContext ctx{model, dir, {}, {}};
  analyses[0]->run(ctx);
  comm->barrier();
  return readHistoryCsv(dir + "/c2_hht.history.csv");
}

TEST(MpiTransient, Sdnl111cIsIdenticalOnOneAndSeveralRanks) {
  auto world = Tpetra::getDefaultComm();
  RCP<const Comm> self = rcp(new Teuchos::MpiComm<int>(MPI_COMM_SELF));
  const std::string base = std::string(CHOC_BINARY_DIR) + "/test-scratch/mpi_transient";
  const HistoryTable par = runC2(base + "/np" + std::to_string(world->getSize()), world);
  // The serial reference on rank 0 (files are written by the world's rank 0 only).
  if (world->getRank() != 0) return;
  const HistoryTable ser = runC2(base + "/self", self);
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
