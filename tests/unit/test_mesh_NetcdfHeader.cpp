// The netCDF header check that runs before the library parses a mesh: valid files of all
// three classic versions pass, and each corruption the fuzzer can produce (a huge count or
// name, a bad tag, type or dimension id, data past the end) is one InputError naming it.
#include <gtest/gtest.h>
#include <netcdf.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/Errors.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "mesh/ExodusReader.hpp"
#include "mesh/NetcdfHeader.hpp"

namespace fs = std::filesystem;
using choc::NetcdfStorage;

namespace {

// Big-endian bytes of a classic file, written field by field after the format specification.
struct ClassicBytes {
  int version = 1;
  std::vector<unsigned char> b;

  ClassicBytes& u(uint64_t v, int bytes) {
    for (int i = bytes - 1; i >= 0; --i) b.push_back(static_cast<unsigned char>(v >> (8 * i)));
    return *this;
  }
  ClassicBytes& count(uint64_t v) { return u(v, version == 5 ? 8 : 4); }
  ClassicBytes& offset(uint64_t v) { return u(v, version == 1 ? 4 : 8); }
  ClassicBytes& name(const std::string& s) {
    count(s.size());
    b.insert(b.end(), s.begin(), s.end());
    while (b.size() % 4) b.push_back(0);
    return *this;
  }
  ClassicBytes& absent() { return u(0, 4).count(0); }
};

// Dimensions n = 3 and the record dimension; variables x(n) (double) and t(record) (double),
// with `records` records written. `tweak` may change the fields before they are laid out.
struct SmallFile {
  int version = 1;
  uint64_t records = 2, nLength = 3, xType = 6, xDim = 0, tDim = 1, dataShift = 0;
  uint64_t dimensionTag = 0x0A, nameLength = 1, dropBytes = 0;
  std::string tDimName = "time";

  std::vector<unsigned char> bytes() const {
    auto header = [&](uint64_t xBegin, uint64_t tBegin) {
      ClassicBytes h;
      h.version = version;
      h.b = {'C', 'D', 'F', static_cast<unsigned char>(version)};
      h.count(records);
      h.u(dimensionTag, 4).count(2);
      if (nameLength == 1) h.name("n"); else h.count(nameLength).u(0x6e000000, 4);
      h.count(nLength).name(tDimName).count(0);
      h.absent();  // global attributes
      h.u(0x0B, 4).count(2);
      h.name("x").count(1).count(xDim).absent().u(xType, 4).count(24).offset(xBegin);
      h.name("t").count(1).count(tDim).absent().u(6, 4).count(8).offset(tBegin);
      return h.b;
    };
    const uint64_t headerSize = header(0, 0).size();
    std::vector<unsigned char> file =
        header(headerSize + dataShift, headerSize + dataShift + 24);
    file.resize(headerSize + 24 + 8 * records, 0);  // zeros as data
    file.resize(file.size() - dropBytes);
    return file;
  }
};

class NetcdfHeader : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(CHOC_BINARY_DIR) / "test-tmp" /
           ("mesh_netcdf_header_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    if (!std::getenv("CHOC_KEEP_TEST_FILES")) fs::remove_all(dir_);
  }

  std::string write(const std::vector<unsigned char>& bytes, const std::string& name = "f.nc") {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    return path;
  }

  // The message of the InputError the check throws for `file` ("" if none).
  std::string error(const SmallFile& file) {
    const std::string path = write(file.bytes());
    try {
      choc::checkNetcdfHeader(path);
    } catch (const choc::InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(path), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
      return m;
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(NetcdfHeader, ValidFilesOfEachClassicVersionPass) {
  for (int version : {1, 2, 5}) {
    SmallFile f;
    f.version = version;
    EXPECT_EQ(choc::checkNetcdfHeader(write(f.bytes())), NetcdfStorage::Classic) << version;
  }
}

// Written by the netCDF library itself, with record variables of 1- and 2-byte types (whose
// records are padded) and attributes of several types: the check agrees with the library.
TEST_F(NetcdfHeader, FilesWrittenByNetcdfInEachClassicVersionPass) {
  for (int mode : {NC_CLASSIC_MODEL, NC_64BIT_OFFSET, NC_64BIT_DATA}) {
    const std::string path = (dir_ / ("lib_" + std::to_string(mode) + ".nc")).string();
    int nc = -1, time = -1, n = -1, x = -1, t = -1, b = -1, s = -1;
    ASSERT_EQ(nc_create(path.c_str(), NC_CLOBBER | mode, &nc), NC_NOERR);
    ASSERT_EQ(nc_def_dim(nc, "time", NC_UNLIMITED, &time), NC_NOERR);
    ASSERT_EQ(nc_def_dim(nc, "n", 5, &n), NC_NOERR);
    const int ints[3] = {1, 2, 3};
    ASSERT_EQ(nc_put_att_int(nc, NC_GLOBAL, "ints", NC_INT, 3, ints), NC_NOERR);
    ASSERT_EQ(nc_put_att_text(nc, NC_GLOBAL, "title", 7, "a title"), NC_NOERR);
    const int bt[2] = {time, n};
    ASSERT_EQ(nc_def_var(nc, "x", NC_DOUBLE, 1, &n, &x), NC_NOERR);
    ASSERT_EQ(nc_def_var(nc, "t", NC_DOUBLE, 1, &time, &t), NC_NOERR);
    ASSERT_EQ(nc_def_var(nc, "b", NC_BYTE, 2, bt, &b), NC_NOERR);
    ASSERT_EQ(nc_def_var(nc, "s", NC_SHORT, 1, &time, &s), NC_NOERR);
    ASSERT_EQ(nc_put_att_text(nc, x, "units", 1, "m"), NC_NOERR);
    ASSERT_EQ(nc_enddef(nc), NC_NOERR);
    const double xs[5] = {0, 1, 2, 3, 4};
    ASSERT_EQ(nc_put_var_double(nc, x, xs), NC_NOERR);
    for (size_t r = 0; r < 7; ++r) {
      const size_t start[2] = {r, 0}, count[2] = {1, 5};
      const double tr = 0.5 * r;
      const signed char br[5] = {1, 2, 3, 4, 5};
      const short sr = static_cast<short>(r);
      ASSERT_EQ(nc_put_var1_double(nc, t, start, &tr), NC_NOERR);
      ASSERT_EQ(nc_put_vara_schar(nc, b, start, count, br), NC_NOERR);
      ASSERT_EQ(nc_put_var1_short(nc, s, start, &sr), NC_NOERR);
    }
    ASSERT_EQ(nc_close(nc), NC_NOERR);
    EXPECT_EQ(choc::checkNetcdfHeader(path), NetcdfStorage::Classic) << mode;
    fs::resize_file(path, fs::file_size(path) - 3);  // into s's last value (2 bytes + padding)
    EXPECT_THROW(choc::checkNetcdfHeader(path), choc::InputError) << mode;
  }
}

TEST_F(NetcdfHeader, FilesWrittenByChocPass) {
  for (int dimension : {1, 3}) {
    choc::BarImpactOptions o;
    o.dimension = dimension;
    const std::string path = (dir_ / "bars.exo").string();
    choc::writeExodusMesh(choc::generateBarImpactMesh(o), path);
    EXPECT_EQ(choc::checkNetcdfHeader(path), NetcdfStorage::Classic) << dimension;
  }
  for (const auto& entry : fs::directory_iterator(fs::path(CHOC_SOURCE_DIR) / "meshes")) {
    if (entry.path().extension() != ".exo") continue;
    EXPECT_EQ(choc::checkNetcdfHeader(entry.path().string()), NetcdfStorage::Classic)
        << entry.path();
  }
}

TEST_F(NetcdfHeader, OtherSignatures) {
  EXPECT_EQ(choc::checkNetcdfHeader(write({})), NetcdfStorage::Unknown);
  EXPECT_EQ(choc::checkNetcdfHeader(write({'C', 'D', 'F', 3, 0, 0, 0, 0})), NetcdfStorage::Unknown);
  const std::string text = "this is not a mesh\n";
  EXPECT_EQ(choc::checkNetcdfHeader(write({text.begin(), text.end()})), NetcdfStorage::Unknown);
  std::vector<unsigned char> hdf5(1024, 0);
  const unsigned char signature[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  std::copy(signature, signature + 8, hdf5.begin() + 512);  // after a 512-byte user block
  EXPECT_EQ(choc::checkNetcdfHeader(write(hdf5)), NetcdfStorage::Hdf5);
}

TEST_F(NetcdfHeader, HugeNameIsRefusedBeforeAllocating) {
  SmallFile f;
  f.nameLength = 0x70000000;  // what netCDF would allocate: 1.8 GB
  EXPECT_NE(error(f).find("the name of dimension 0 is 1879048192 bytes long"), std::string::npos);
  f.nameLength = 0;
  EXPECT_NE(error(f).find("is 0 bytes long"), std::string::npos);
}

TEST_F(NetcdfHeader, HugeCountIsRefused) {
  for (int version : {1, 5}) {
    SmallFile f;
    f.version = version;
    f.nLength = uint64_t{1} << (version == 5 ? 62 : 30);  // x(n) then needs 8 GB or more
    EXPECT_NE(error(f).find("variable 'x' needs more than"), std::string::npos)
        << version;
  }
  SmallFile negative;
  negative.nLength = 0x80000000u;
  EXPECT_NE(error(negative).find("the length of dimension 'n' is negative"), std::string::npos);
}

TEST_F(NetcdfHeader, BadTagTypeOrDimensionIdIsRefused) {
  SmallFile tag;
  tag.dimensionTag = 0x0B;
  EXPECT_NE(error(tag).find("the dimension list has tag 11"), std::string::npos);
  SmallFile type;
  type.xType = 7;  // NC_UBYTE exists only in CDF-5
  EXPECT_NE(error(type).find("variable 'x' has unknown type 7"), std::string::npos);
  type.version = 5;
  EXPECT_EQ(error(type), "");
  SmallFile id;
  id.xDim = 2;
  EXPECT_NE(error(id).find("variable 'x' uses dimension id 2 but the file has 2"), std::string::npos);
  SmallFile sameName;
  sameName.tDimName = "n";
  EXPECT_NE(error(sameName).find("two dimensions are named 'n'"), std::string::npos);
  SmallFile twoRecordDims;
  twoRecordDims.nLength = 0;
  EXPECT_NE(error(twoRecordDims).find("'time' is a second record dimension"), std::string::npos);
}

TEST_F(NetcdfHeader, DataOutsideTheFileIsRefused) {
  SmallFile cut;
  cut.dropBytes = 1;  // the last record of t
  EXPECT_NE(error(cut).find("variable 't' needs 16 bytes"), std::string::npos);
  cut.records = 0;
  cut.dropBytes = 1;  // x itself
  EXPECT_NE(error(cut).find("variable 'x' needs 24 bytes"), std::string::npos);
  SmallFile shifted;
  shifted.dataShift = static_cast<uint64_t>(-8);  // x would start inside the header
  EXPECT_NE(error(shifted).find("variable 'x' starts at byte"), std::string::npos);
  EXPECT_NE(error(shifted).find("inside the header"), std::string::npos);
}

TEST_F(NetcdfHeader, EveryTruncationOfAChocMeshIsAnInputError) {
  choc::BarImpactOptions o;
  o.dimension = 3;
  const std::string path = (dir_ / "whole.exo").string();
  choc::writeExodusMesh(choc::generateBarImpactMesh(o), path);
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> whole((std::istreambuf_iterator<char>(in)), {});
  for (std::size_t keep = 4; keep < whole.size(); keep += 7) {
    const std::string cut = write({whole.begin(), whole.begin() + static_cast<long>(keep)});
    EXPECT_THROW(choc::checkNetcdfHeader(cut), choc::InputError) << keep << " bytes";
  }
}

}  // namespace
