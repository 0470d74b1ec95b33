// Exodus mesh writer and reader: round trips (classic and netCDF-4), padding of 1D/2D files,
// topology names, and one-line InputErrors naming the path for files that are missing, not
// Exodus, or corrupt in the ways the fuzzer found.
#include <gtest/gtest.h>
#include <exodusII.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <utility>
#include <vector>

#include "core/Errors.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "mesh/ExodusReader.hpp"
#include "test_mesh_helpers.hpp"

namespace fs = std::filesystem;

namespace {

class ExodusIO : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(CHOC_BINARY_DIR) / "test-tmp" /
           ("mesh_exodus_io_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

TEST_F(ExodusIO, RoundTrip1D) {
  choc::BarImpactOptions o;
  o.shiftA = -1.1e-5;
  const choc::Mesh mesh = choc::generateBarImpactMesh(o);
  choc::writeExodusMesh(mesh, file("bars1d.exo"));
  const choc::Mesh back = choc::readExodusMesh(file("bars1d.exo"));
  expectSameMesh(mesh, back);
  EXPECT_EQ(back.title, mesh.title);
}

TEST_F(ExodusIO, RoundTrip3D) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  o.axis = 'y';
  o.across1 = 2;
  o.across2 = 3;
  o.along1 = o.along2 = 7;
  const choc::Mesh mesh = choc::generateBarImpactMesh(o);
  choc::writeExodusMesh(mesh, file("bars3d.exo"));
  const choc::Mesh back = choc::readExodusMesh(file("bars3d.exo"));
  expectSameMesh(mesh, back);
  // sideNodes works identically on the mesh read back.
  const choc::SideSet* ss = back.findSideSet("CNT_POU2");
  ASSERT_NE(ss, nullptr);
  EXPECT_EQ(back.sideNodes(ss->elements[0], ss->sides[0]),
            mesh.sideNodes(ss->elements[0], ss->sides[0]));
}

TEST_F(ExodusIO, EmptyBlockAndLongNamesRoundTrip) {
  choc::Mesh mesh = choc::generateBarImpactMesh({});
  choc::ElementBlock empty;
  empty.name = "AN_ELEMENT_BLOCK_NAME_LONGER_THAN_THIRTY_TWO";
  empty.id = 9;
  empty.topology = "HEX8";
  empty.nodesPerElement = 8;
  mesh.blocks.push_back(empty);
  mesh.nodeSets.push_back({"EMPTY_SET", 40, {}});
  choc::writeExodusMesh(mesh, file("empty_block.exo"));
  choc::Mesh back = choc::readExodusMesh(file("empty_block.exo"));
  // Exodus keeps no type for an empty block.
  EXPECT_EQ(back.blocks[2].name, empty.name);
  EXPECT_EQ(back.blocks[2].id, 9);
  EXPECT_EQ(back.blocks[2].numElements(), 0);
  EXPECT_EQ(back.blocks[2].topology, "");
  back.blocks[2].topology = "HEX8";
  back.blocks[2].nodesPerElement = 8;
  expectSameMesh(mesh, back);
  // ... and such a block writes and reads again.
  choc::writeExodusMesh(back, file("empty_block2.exo"));
  EXPECT_EQ(choc::readExodusMesh(file("empty_block2.exo")).blocks[2].numElements(), 0);
}

TEST_F(ExodusIO, WriterRefusesBadMeshWithoutLeavingAFile) {
  choc::Mesh mesh = choc::generateBarImpactMesh({});
  mesh.blocks[1].connectivity[0] = 500;  // node index out of range
  EXPECT_THROW(choc::writeExodusMesh(mesh, file("bad.exo")), std::invalid_argument);
  EXPECT_FALSE(fs::exists(file("bad.exo")));
  try {
    choc::writeExodusMesh(choc::generateBarImpactMesh({}), file("no/such/dir/x.exo"));
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(file("no/such/dir/x.exo")), std::string::npos);
  }
}

// A file written directly with the Exodus API: num_dim dimensions, one block.
void writeRaw(const std::string& path, int dim, const char* topology, int nodesPerElement,
              bool named) {
  int cpu = 8, io = 8;
  const int id = ex_create(path.c_str(), EX_CLOBBER, &cpu, &io);
  ASSERT_GE(id, 0);
  const int nodes = nodesPerElement;
  ASSERT_EQ(ex_put_init(id, "raw", dim, nodes, 1, 1, 0, 0), 0);
  std::vector<double> x(nodes), y(nodes, 2.0), z(nodes, 3.0);
  for (int n = 0; n < nodes; ++n) x[n] = n;
  ASSERT_EQ(ex_put_coord(id, x.data(), dim > 1 ? y.data() : nullptr, dim > 2 ? z.data() : nullptr), 0);
  ASSERT_EQ(ex_put_block(id, EX_ELEM_BLOCK, 42, topology, 1, nodesPerElement, 0, 0, 0), 0);
  std::vector<int> conn(nodesPerElement);
  for (int n = 0; n < nodesPerElement; ++n) conn[n] = n + 1;
  ASSERT_EQ(ex_put_conn(id, EX_ELEM_BLOCK, 42, conn.data(), nullptr, nullptr), 0);
  if (named) {
    char name[] = "PIPE";
    char* names[1] = {name};
    ASSERT_EQ(ex_put_names(id, EX_ELEM_BLOCK, names), 0);
  }
  ASSERT_EQ(ex_close(id), 0);
}

TEST_F(ExodusIO, ReadsTwoDimensionalFilePaddedWithZeros) {
  writeRaw(file("d2.exo"), 2, "truss", 2, true);
  const choc::Mesh m = choc::readExodusMesh(file("d2.exo"));
  ASSERT_EQ(m.numNodes(), 2);
  EXPECT_EQ(m.coords[1], (choc::Point3{1.0, 2.0, 0.0}));
  EXPECT_EQ(m.blocks[0].name, "PIPE");
  EXPECT_EQ(m.blocks[0].topology, "BEAM2");
  EXPECT_EQ(m.blocks[0].connectivity, (std::vector<int>{0, 1}));
}

TEST_F(ExodusIO, ReadsOneDimensionalUnnamedBlock) {
  writeRaw(file("d1.exo"), 1, "BAR2", 2, false);
  const choc::Mesh m = choc::readExodusMesh(file("d1.exo"));
  EXPECT_EQ(m.coords[1], (choc::Point3{1.0, 0.0, 0.0}));
  EXPECT_EQ(m.blocks[0].name, "block_42");
  EXPECT_EQ(m.blocks[0].id, 42);
}

TEST(ExodusTopology, CanonicalNames) {
  for (const char* t : {"BAR2", "BAR", "BEAM", "BEAM2", "TRUSS", "TRUSS2", "bar2", " beam "})
    EXPECT_EQ(choc::canonicalTopology(t, 2), "BEAM2") << t;
  for (const char* t : {"HEX", "HEX8", "hex8"}) EXPECT_EQ(choc::canonicalTopology(t, 8), "HEX8");
  EXPECT_EQ(choc::canonicalTopology("HEX", 27), "");
  EXPECT_EQ(choc::canonicalTopology("BAR", 3), "");
  EXPECT_EQ(choc::canonicalTopology("TETRA", 4), "TET4");
  EXPECT_EQ(choc::canonicalTopology("TETRA", 10), "TET10");
  EXPECT_EQ(choc::canonicalTopology("tetra10", 10), "TET10");
  EXPECT_EQ(choc::canonicalTopology("HEX", 20), "HEX20");
  EXPECT_EQ(choc::canonicalTopology("TRIANGLE", 6), "TRI6");
  EXPECT_EQ(choc::canonicalTopology("QUAD", 8), "QUAD8");
  EXPECT_EQ(choc::canonicalTopology("SHELL4", 4), "");  // shells are not solids
  EXPECT_EQ(choc::canonicalTopology("WEDGE", 6), "");
  EXPECT_EQ(choc::canonicalTopology("TETRA", 8), "");
}

// Reads path expecting an InputError; the message must be one line naming the path, and
// nothing may be printed on stderr by the libraries.
std::string readError(const std::string& path) {
  ::testing::internal::CaptureStderr();
  std::string message;
  try {
    choc::readExodusMesh(path);
  } catch (const choc::InputError& e) {
    message = e.what();
  }
  const std::string noise = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(noise, "");
  EXPECT_NE(message, "") << "no InputError for " << path;
  EXPECT_NE(message.find(path), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  return message;
}

TEST_F(ExodusIO, UnsupportedTopologyNamesBlockAndSupportedOnes) {
  writeRaw(file("wedge.exo"), 3, "WEDGE", 6, true);  // a prism: not supported
  const std::string m = readError(file("wedge.exo"));
  EXPECT_NE(m.find("PIPE"), std::string::npos) << m;
  EXPECT_NE(m.find("WEDGE"), std::string::npos) << m;
  EXPECT_NE(m.find("TET10"), std::string::npos) << m;
  EXPECT_NE(m.find("BEAM2"), std::string::npos) << m;
  EXPECT_NE(m.find("HEX8"), std::string::npos) << m;
}

TEST_F(ExodusIO, MissingFile) {
  EXPECT_NE(readError(file("does_not_exist.exo")).find("not found"), std::string::npos);
}

TEST_F(ExodusIO, EmptyFile) {
  std::ofstream(file("empty.exo")).close();
  readError(file("empty.exo"));
}

TEST_F(ExodusIO, TextFile) {
  std::ofstream(file("text.exo")) << "this is not an Exodus file\n1 2 3\n";
  readError(file("text.exo"));
}

TEST_F(ExodusIO, Directory) { readError(dir_.string()); }

TEST_F(ExodusIO, TruncatedFile) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  choc::writeExodusMesh(choc::generateBarImpactMesh(o), file("cut.exo"));
  const auto size = fs::file_size(file("cut.exo"));
  for (auto keep : {size / 2, size / 8, std::uintmax_t{100}, size - 8}) {
    fs::copy_file(file("cut.exo"), file("cut_part.exo"), fs::copy_options::overwrite_existing);
    fs::resize_file(file("cut_part.exo"), keep);
    readError(file("cut_part.exo"));
  }
}


// Swaps two equally long byte strings everywhere in a file.
void swapInFile(const std::string& path, const std::string& a, const std::string& b) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), {});
  in.close();
  const std::string marker(a.size(), '\x01');
  for (auto [from, to] : {std::pair{a, marker}, std::pair{b, a}, std::pair{marker, b}})
    for (auto at = bytes.find(from); at != std::string::npos; at = bytes.find(from, at + 1))
      bytes.replace(at, from.size(), to);
  std::ofstream(path, std::ios::binary) << bytes;
}

// Found by the fuzzer: a node set's Exodus dimension (num_nod_ns1) shorter than its netCDF
// variable (node_ns1), which netCDF writes whole into the buffer sized by the dimension.
TEST_F(ExodusIO, SetVariableLongerThanItsDimensionIsRefused) {
  choc::BarImpactOptions o;  // node sets A, B, C, D (1 node each), POU1, POU2 (a bar each)
  const std::string path = file("swapped.exo");
  choc::writeExodusMesh(choc::generateBarImpactMesh(o), path);
  swapInFile(path, std::string("num_nod_ns1\0", 12), std::string("num_nod_ns5\0", 12));
  const std::string m = readError(path);
  EXPECT_NE(m.find("variable 'node_ns1' holds 1 values but its Exodus dimensions declare"),
            std::string::npos) << m;
}


TEST_F(ExodusIO, RoundTripNetcdf4) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  const choc::Mesh mesh = choc::generateBarImpactMesh(o);
  choc::writeExodusMesh(mesh, file("nc4.exo"), true);
  std::ifstream in(file("nc4.exo"), std::ios::binary);
  char signature[4] = {};
  in.read(signature, 4);
  ASSERT_EQ(std::string(signature + 1, 3), "HDF");  // read by a child process through HDF5
  expectSameMesh(mesh, choc::readExodusMesh(file("nc4.exo")));
}


// Found by fuzzing (valgrind: stack smashing inside the Exodus library, or choc's ex_block
// overwritten): attributes that Exodus reads into fixed-size buffers, grown with the netCDF
// API on a valid mesh, are refused before Exodus reads them. A long title is read (Exodus
// truncates it safely).
TEST_F(ExodusIO, AttributesLongerThanExodusBuffersAreRefused) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  struct Case {
    const char* name;
    std::function<int(int)> grow;  // on the open netCDF file, in define mode
    const char* message;
  };
  const std::vector<float> versions(200, 8.0f);
  const std::vector<int> lengths(200, 32);
  const std::string longType = "HEX8" + std::string(300, 'x');
  const std::string longTitle(400, 'T');
  const std::vector<Case> cases = {
      {"version", [&](int nc) { return nc_put_att_float(nc, NC_GLOBAL, "version", NC_FLOAT, 200, versions.data()); },
       "global attribute 'version' has 200 values (Exodus reads exactly one)"},
      {"maxname", [&](int nc) { return nc_put_att_int(nc, NC_GLOBAL, "maximum_name_length", NC_INT, 200, lengths.data()); },
       "global attribute 'maximum_name_length' has 200 values"},
      {"elemtype", [&](int nc) {
         int var = -1;
         const int rc = nc_inq_varid(nc, "connect1", &var);
         return rc != NC_NOERR ? rc : nc_put_att_text(nc, var, "elem_type", longType.size(), longType.c_str());
       },
       "attribute 'elem_type' of variable 'connect1' has 304 characters (Exodus reads at most 32)"},
      {"title", [&](int nc) { return nc_put_att_text(nc, NC_GLOBAL, "title", longTitle.size(), longTitle.c_str()); },
       nullptr},
  };
  for (const Case& c : cases) {
    const std::string path = file(std::string("grown_") + c.name + ".exo");
    choc::writeExodusMesh(choc::generateBarImpactMesh(o), path);
    int nc = -1;
    ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &nc), NC_NOERR);
    ASSERT_EQ(nc_redef(nc), NC_NOERR);
    ASSERT_EQ(c.grow(nc), NC_NOERR) << c.name;
    ASSERT_EQ(nc_close(nc), NC_NOERR);
    if (!c.message) {
      EXPECT_NO_THROW(choc::readExodusMesh(path)) << c.name;
      continue;
    }
    const std::string m = readError(path);
    EXPECT_NE(m.find(c.message), std::string::npos) << m;
  }
}


// Found by fuzzing (valgrind: an invalid write in ex_id_lkup): exodus reads a status variable
// whole into a buffer sized by the entity count; a longer one is refused.
TEST_F(ExodusIO, StatusVariableLongerThanTheEntityCountIsRefused) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  const std::string path = file("long_status.exo");
  choc::writeExodusMesh(choc::generateBarImpactMesh(o), path);
  int nc = -1, big = -1, var = -1, old = -1;
  ASSERT_EQ(nc_open(path.c_str(), NC_WRITE, &nc), NC_NOERR);
  ASSERT_EQ(nc_redef(nc), NC_NOERR);
  ASSERT_EQ(nc_inq_varid(nc, "eb_status", &old), NC_NOERR);
  ASSERT_EQ(nc_rename_var(nc, old, "eb_status_old"), NC_NOERR);
  ASSERT_EQ(nc_def_dim(nc, "big", 500, &big), NC_NOERR);
  ASSERT_EQ(nc_def_var(nc, "eb_status", NC_INT, 1, &big, &var), NC_NOERR);
  ASSERT_EQ(nc_enddef(nc), NC_NOERR);
  const std::vector<int> ones(500, 1);
  ASSERT_EQ(nc_put_var_int(nc, var, ones.data()), NC_NOERR);
  ASSERT_EQ(nc_close(nc), NC_NOERR);
  const std::string m = readError(path);
  EXPECT_NE(m.find("element block status: variable 'eb_status' holds 500 values but its Exodus "
                   "dimensions declare 2"),
            std::string::npos) << m;
}

}  // namespace
