// ExodusResultsWriter: steps read back through the Exodus API, .part / final /
// .incomplete names, refusal of non-finite values.
#include <gtest/gtest.h>
#include <exodusII.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/ExodusReader.hpp"
#include "output/ExodusResults.hpp"

namespace fs = std::filesystem;

namespace {

class ExodusResults : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(CHOC_BINARY_DIR) / "test-tmp" /
           ("output_exodus_results_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    choc::BarImpactOptions o;
    o.dimension = 3;
    o.along1 = o.along2 = 3;
    mesh_ = choc::generateBarImpactMesh(o);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }

  // nodal[v][n] = 1000 v + n + step / 10
  std::vector<std::vector<double>> nodal(int vars, int step) const {
    std::vector<std::vector<double>> f(vars, std::vector<double>(mesh_.numNodes()));
    for (int v = 0; v < vars; ++v)
      for (int n = 0; n < mesh_.numNodes(); ++n) f[v][n] = 1000.0 * v + n + step / 10.0;
    return f;
  }

  fs::path dir_;
  choc::Mesh mesh_;
};

std::vector<std::string> variableNames(int exoid, ex_entity_type type) {
  int count = 0;
  EXPECT_EQ(ex_get_variable_param(exoid, type, &count), 0);
  std::vector<std::vector<char>> buffers(count, std::vector<char>(MAX_STR_LENGTH + 1));
  std::vector<char*> pointers;
  for (auto& b : buffers) pointers.push_back(b.data());
  if (count > 0) {
    EXPECT_EQ(ex_get_variable_names(exoid, type, count, pointers.data()), 0);
  }
  std::vector<std::string> names;
  for (auto& b : buffers) names.emplace_back(b.data());
  return names;
}

TEST_F(ExodusResults, ThreeStepsReadBack) {
  const std::vector<std::string> nodalNames = {"DISP_X", "DISP_Y", "DISP_Z", "VEL_X"};
  const std::vector<std::string> globalNames = {"energy_kinetic", "energy_total"};
  const std::string path = file("run.exo");
  {
    choc::ExodusResultsWriter w(path, mesh_, nodalNames, globalNames);
    EXPECT_TRUE(fs::exists(path + ".part"));
    EXPECT_FALSE(fs::exists(path));
    for (int s = 0; s < 3; ++s) w.writeStep(1e-6 * (s + 1), nodal(4, s), {10.0 + s, 20.0 + s});
    EXPECT_EQ(w.stepsWritten(), 3);
    // Readable before finish (each step is flushed).
    int cpu = 8, io = 0;
    float version = 0;
    const int id = ex_open((path + ".part").c_str(), EX_READ, &cpu, &io, &version);
    ASSERT_GE(id, 0);
    EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 3);
    ex_close(id);
    w.finish();
    EXPECT_FALSE(fs::exists(path + ".part"));
    EXPECT_TRUE(fs::exists(path));
    EXPECT_THROW(w.writeStep(1.0, nodal(4, 0), {0, 0}), std::logic_error);
  }
  EXPECT_TRUE(fs::exists(path));  // destructor after finish leaves the file alone
  EXPECT_FALSE(fs::exists(file("run.incomplete.exo")));

  int cpu = 8, io = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(variableNames(id, EX_NODAL), nodalNames);
  EXPECT_EQ(variableNames(id, EX_GLOBAL), globalNames);
  ASSERT_EQ(ex_inquire_int(id, EX_INQ_TIME), 3);
  std::vector<double> times(3);
  ASSERT_EQ(ex_get_all_times(id, times.data()), 0);
  EXPECT_EQ(times, (std::vector<double>{1e-6, 2e-6, 3e-6}));
  for (int s = 0; s < 3; ++s) {
    const auto expected = nodal(4, s);
    for (int v = 0; v < 4; ++v) {
      std::vector<double> values(mesh_.numNodes());
      ASSERT_EQ(ex_get_var(id, s + 1, EX_NODAL, v + 1, 1, mesh_.numNodes(), values.data()), 0);
      EXPECT_EQ(values, expected[v]) << "step " << s << " variable " << v;
    }
    std::vector<double> globals(2);
    ASSERT_EQ(ex_get_var(id, s + 1, EX_GLOBAL, 1, 1, 2, globals.data()), 0);
    EXPECT_EQ(globals, (std::vector<double>{10.0 + s, 20.0 + s}));
  }
  ex_close(id);
  // The mesh part reads back unchanged.
  const choc::Mesh back = choc::readExodusMesh(path);
  EXPECT_EQ(back.coords, mesh_.coords);
  EXPECT_EQ(back.blockNames(), mesh_.blockNames());
  EXPECT_EQ(back.nodeSetNames(), mesh_.nodeSetNames());
  EXPECT_EQ(back.sideSetNames(), mesh_.sideSetNames());
}

// Element variables on the first block only: the truth table says so, block 1's values read
// back per element in order, and a non-finite element value writes nothing of its step.
TEST_F(ExodusResults, ElementVariablesOnTheirBlocks) {
  ASSERT_GE(mesh_.blocks.size(), 2u);
  const std::string path = file("elements.exo");
  const int total = mesh_.numElements(), first = mesh_.blocks[0].numElements();
  const std::vector<std::string> names = {"SIGMA_XX", "STRAIN_ENERGY_DENSITY"};
  auto values = [&](int step) {
    std::vector<std::vector<double>> f(2, std::vector<double>(size_t(total), 0.0));
    for (int v = 0; v < 2; ++v)
      for (int e = 0; e < first; ++e) f[size_t(v)][size_t(e)] = 100.0 * v + e + step / 10.0;
    return f;
  };
  {
    choc::ExodusResultsWriter w(path, mesh_, {"DISP_X"}, {}, choc::ElementVariables{names, {1, 0}});
    for (int s = 0; s < 2; ++s) w.writeStep(1e-6 * (s + 1), nodal(1, s), {}, values(s));
    auto bad = values(2);
    bad[1][0] = std::nan("");
    EXPECT_THROW(w.writeStep(3e-6, nodal(1, 2), {}, bad), choc::NumericalError);
    EXPECT_EQ(w.stepsWritten(), 2);
    w.finish();
  }
  int cpu = 8, io = 0;
  float version = 0;
  const int id = ex_open(path.c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(variableNames(id, EX_ELEM_BLOCK), names);
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 2);
  const int blocks = static_cast<int>(mesh_.blocks.size());
  std::vector<int> table(static_cast<size_t>(blocks) * 2);
  ASSERT_EQ(ex_get_truth_table(id, EX_ELEM_BLOCK, blocks, 2, table.data()), 0);
  EXPECT_EQ(table[0], 1);
  EXPECT_EQ(table[1], 1);
  EXPECT_EQ(table[2], 0);
  EXPECT_EQ(table[3], 0);
  std::vector<int> ids(static_cast<size_t>(blocks));
  ASSERT_EQ(ex_get_ids(id, EX_ELEM_BLOCK, ids.data()), 0);
  for (int s = 0; s < 2; ++s)
    for (int v = 0; v < 2; ++v) {
      std::vector<double> got(static_cast<size_t>(first));
      ASSERT_EQ(ex_get_var(id, s + 1, EX_ELEM_BLOCK, v + 1, ids[0], first, got.data()), 0);
      const auto expected = values(s)[size_t(v)];
      EXPECT_EQ(got, std::vector<double>(expected.begin(), expected.begin() + first)) << "step " << s;
    }
  ex_close(id);
}

TEST_F(ExodusResults, AbandonRenamesToIncomplete) {
  const std::string path = file("sub/run.exo");
  fs::create_directories(file("sub"));
  choc::ExodusResultsWriter w(path, mesh_, {"DISP_X"}, {});
  w.writeStep(0.5, nodal(1, 0), {});
  w.abandon();
  EXPECT_EQ(w.incompletePath(), file("sub/run.incomplete.exo"));
  EXPECT_TRUE(fs::exists(file("sub/run.incomplete.exo")));
  EXPECT_FALSE(fs::exists(path + ".part"));
  EXPECT_FALSE(fs::exists(path));
  EXPECT_NO_THROW(w.abandon());  // quiet when already closed
  int cpu = 8, io = 0;
  float version = 0;
  const int id = ex_open(file("sub/run.incomplete.exo").c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 1);
  ex_close(id);
}

TEST_F(ExodusResults, DestructorAbandons) {
  { choc::ExodusResultsWriter w(file("quit.exo"), mesh_, {"A"}, {"G"}); }
  EXPECT_TRUE(fs::exists(file("quit.incomplete.exo")));
  EXPECT_FALSE(fs::exists(file("quit.exo.part")));
  EXPECT_FALSE(fs::exists(file("quit.exo")));
}

TEST_F(ExodusResults, NonFiniteValuesAreRefused) {
  choc::ExodusResultsWriter w(file("nan.exo"), mesh_, {"DISP_X", "VEL_Z"}, {"energy"});
  w.writeStep(1e-6, nodal(2, 0), {1.0});
  auto fields = nodal(2, 1);
  fields[1][5] = std::nan("");
  try {
    w.writeStep(2e-6, fields, {1.0});
    FAIL() << "NaN written";
  } catch (const choc::NumericalError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("VEL_Z"), std::string::npos) << m;
    EXPECT_NE(m.find("2e-06"), std::string::npos) << m;
  }
  try {
    w.writeStep(2e-6, nodal(2, 1), {INFINITY});
    FAIL() << "inf written";
  } catch (const choc::NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("energy"), std::string::npos) << e.what();
  }
  EXPECT_THROW(w.writeStep(NAN, nodal(2, 1), {1.0}), choc::NumericalError);
  EXPECT_EQ(w.stepsWritten(), 1);
  EXPECT_THROW(w.writeStep(3e-6, nodal(1, 1), {1.0}), std::invalid_argument);  // sizes
  w.finish();
  int cpu = 8, io = 0;
  float version = 0;
  const int id = ex_open(file("nan.exo").c_str(), EX_READ, &cpu, &io, &version);
  ASSERT_GE(id, 0);
  EXPECT_EQ(ex_inquire_int(id, EX_INQ_TIME), 1);  // nothing of the refused steps
  ex_close(id);
}

TEST_F(ExodusResults, IoFailureNamesThePath) {
  const std::string path = file("missing_dir/run.exo");
  try {
    choc::ExodusResultsWriter w(path, mesh_, {"DISP_X"}, {});
    FAIL() << "created in a missing directory";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  EXPECT_THROW(choc::ExodusResultsWriter(file("dup.exo"), mesh_, {"A", "A"}, {}),
               std::invalid_argument);
  EXPECT_FALSE(fs::exists(file("dup.exo.part")));
}

}  // namespace
