// Checkpoint records and files: round trip, missing and malformed records, truncation and
// corruption refused, the previous checkpoint kept when a write fails.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "core/Errors.hpp"
#include "restart/CheckpointFile.hpp"
#include "restart/RunIdentity.hpp"

namespace choc {
namespace {

struct Pod {
  double x;
  int n;
  bool b;
};

StateArchive sample() {
  StateArchive a;
  a.putDouble("t", 1.25e-4);
  a.putInt("n", 123456789012LL);
  a.putVector("v", std::vector<double>{1.0, -2.5, 3e-300});
  a.putVector("s", std::vector<char>{1, 0, 1});
  a.putText("name", "c1_modified");
  a.putPod("pod", Pod{0.5, 7, true});
  return a;
}

std::string tempPath(const char* name) {
  return (std::filesystem::temp_directory_path() / (std::string("choc_test_") + name)).string();
}

TEST(StateArchive, RoundTripIsExact) {
  const StateArchive b = StateArchive::parse(sample().serialize());
  EXPECT_EQ(b.size(), 6u);
  EXPECT_EQ(b.getDouble("t"), 1.25e-4);
  EXPECT_EQ(b.getInt("n"), 123456789012LL);
  EXPECT_EQ(b.getVector<double>("v", 3), (std::vector<double>{1.0, -2.5, 3e-300}));
  EXPECT_EQ(b.getVector<char>("s"), (std::vector<char>{1, 0, 1}));
  EXPECT_EQ(b.text("name"), "c1_modified");
  const Pod p = b.getPod<Pod>("pod");
  EXPECT_EQ(p.x, 0.5);
  EXPECT_EQ(p.n, 7);
  EXPECT_TRUE(p.b);
}

TEST(StateArchive, MissingOrMisSizedRecordsAreErrors) {
  const StateArchive a = sample();
  EXPECT_THROW(a.getDouble("absent"), StateRecordError);
  EXPECT_THROW(a.getVector<double>("v", 4), StateRecordError);
  EXPECT_THROW(a.getDouble("v"), StateRecordError);  // three values, not one
  std::vector<char> bytes = sample().serialize();
  bytes.pop_back();
  EXPECT_THROW(StateArchive::parse(bytes), StateRecordError);
}

TEST(CheckpointFile, WriteReadAndRefuseDamage) {
  const std::string path = tempPath("archive.checkpoint");
  writeCheckpointFile(path, sample());
  EXPECT_FALSE(std::filesystem::exists(path + ".tmp"));
  EXPECT_EQ(readCheckpointFile(path).getVector<double>("v", 3)[1], -2.5);
  std::ifstream in(path, std::ios::binary);
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  auto writeBytes = [&](const std::vector<char>& d) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(d.data(), static_cast<std::streamsize>(d.size()));
  };
  std::vector<char> flipped = data;
  flipped[flipped.size() / 2] ^= 0x10;
  writeBytes(flipped);
  EXPECT_THROW(readCheckpointFile(path), InputError);
  writeBytes(std::vector<char>(data.begin(), data.begin() + static_cast<long>(data.size() - 3)));
  EXPECT_THROW(readCheckpointFile(path), InputError);
  writeBytes(data);
  EXPECT_NO_THROW(readCheckpointFile(path));
  std::remove(path.c_str());
  EXPECT_THROW(readCheckpointFile(path), InputError);
}

TEST(CheckpointFile, UnwritableDirectoryKeepsNothingHalfWritten) {
  EXPECT_THROW(writeCheckpointFile("/nonexistent-dir/x.checkpoint", sample()), OutputError);
}

TEST(RunIdentity, NamesTheFirstDifferingParameter) {
  Teuchos::ParameterList in;
  in.sublist("Analyses").sublist("c").set("Time Step", 1e-6);
  in.sublist("Analyses").sublist("c").set("End Time", 1e-3);
  in.sublist("Analyses").sublist("c").sublist("Checkpoint").set("Interval Steps", 10);
  RunIdentity was{"c", canonicalInput(in, "c"), 1, 1};
  // End Time and checkpoint settings may change on restart.
  in.sublist("Analyses").sublist("c").set("End Time", 2e-3);
  in.sublist("Analyses").sublist("c").sublist("Checkpoint").set("Interval Steps", 20);
  RunIdentity now{"c", canonicalInput(in, "c"), 1, 2};
  EXPECT_EQ(was.mismatch(now), "");
  in.sublist("Analyses").sublist("c").set("Time Step", 5e-7);
  now.input = canonicalInput(in, "c");
  EXPECT_EQ(was.mismatch(now),
            "parameter 'Analyses/c/Time Step' is '5e-07' in the input, '1e-06' in the checkpoint");
  now.input = was.input;
  now.mesh = 2;
  EXPECT_NE(was.mismatch(now).find("the mesh differs"), std::string::npos);
}

}  // namespace
}  // namespace choc
