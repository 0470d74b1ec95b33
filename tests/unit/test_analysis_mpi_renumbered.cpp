// SDNL111 C (Lagrange contact, full HHT) on its HEX8 mesh and on the same mesh with the nodes
// randomly renumbered: the same histories to solver tolerance (run by ctest on 1 and on 2
// ranks; with the 2-rank run of test_analysis_mpi_transient.cpp against the serial one, the
// histories do not depend on the numbering nor on the number of ranks).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>

#include "analysis/ImplicitTransient.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "mesh/ExodusReader.hpp"
#include "test_analysis_contact_helpers.hpp"

namespace choc {
namespace {

// new index = perm[old]; elements and sets keep their order, their nodes follow.
Mesh renumbered(const Mesh& m, unsigned seed) {
  std::vector<int> perm(m.numNodes());
  std::iota(perm.begin(), perm.end(), 0);
  std::shuffle(perm.begin(), perm.end(), std::mt19937(seed));
  Mesh r = m;
  for (int i = 0; i < m.numNodes(); ++i) r.coords[perm[i]] = m.coords[i];
  for (auto& b : r.blocks)
    for (int& n : b.connectivity) n = perm[n];
  for (auto& s : r.nodeSets)
    for (int& n : s.nodes) n = perm[n];
  return r;
}

HistoryTable runC2(const std::string& dir, const std::string& mesh, RCP<const Comm> comm) {
  std::filesystem::create_directories(dir);
  const std::string file = std::string(CHOC_SOURCE_DIR) + "/input/sdnl111c.xml";
  auto input = readXmlParameters(file);
  input->sublist("Mesh").set("File", mesh);
  validate(*input, topLevelParameters(), InputLocation{file, ""});
  auto& an = input->sublist("Analyses");
  an.remove("c1_modified");
  an.sublist("c2_hht").set("End Time", 4e-4);
  an.sublist("c2_hht").set("Exodus Interval", 0);
  an.sublist("c2_hht").remove("Checks");
  validateAnalyses(an, file);
  Model model(*input, file, comm);
  auto analyses = createAnalyses(an, file);
  setupAnalyses(analyses, model);
  RunContext ctx{model, dir, {}, {}};
  analyses[0]->run(ctx);
  comm->barrier();
  return readHistoryCsv(dir + "/c2_hht.history.csv");
}

TEST(MpiRenumbered, Sdnl111cDoesNotDependOnTheNodeNumbering) {
  auto comm = Tpetra::getDefaultComm();
  const std::string base = std::string(CHOC_BINARY_DIR) + "/test-scratch/renumbered/np" +
                           std::to_string(comm->getSize());
  std::filesystem::create_directories(base);
  const std::string original = std::string(CHOC_SOURCE_DIR) + "/meshes/sdnl111_3d.exo";
  const std::string shuffled = base + "/sdnl111_3d_renumbered.exo";
  if (comm->getRank() == 0) writeExodusMesh(renumbered(readExodusMesh(original), 2026), shuffled);
  comm->barrier();
  const HistoryTable a = runC2(base + "/original", original, comm);
  const HistoryTable b = runC2(base + "/renumbered", shuffled, comm);
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
