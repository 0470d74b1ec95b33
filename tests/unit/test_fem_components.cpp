#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "fem/Components.hpp"

using namespace choc;

TEST(Components, NamesRoundTrip) {
  const char* names[] = {"DX", "DY", "DZ", "DRX", "DRY", "DRZ"};
  for (int c = 0; c < kNumComponents; ++c) {
    EXPECT_STREQ(componentName(c), names[c]);
    EXPECT_EQ(componentFromName(names[c]), c);
  }
  EXPECT_EQ(componentFromName("drz"), DRZ);
  EXPECT_EQ(componentFromName("Dy"), DY);
  EXPECT_EQ(componentFromName("DW"), -1);
  EXPECT_EQ(componentFromName(""), -1);
  EXPECT_EQ(componentFromName("DXX"), -1);
}

TEST(Components, ParsesSeparatorsCaseAndDuplicates) {
  EXPECT_EQ(parseComponents("DX DY"), (std::vector<int>{DX, DY}));
  EXPECT_EQ(parseComponents("dz,dx"), (std::vector<int>{DX, DZ}));
  EXPECT_EQ(parseComponents("  DRZ , dx,,DX\tdRy "), (std::vector<int>{DX, DRY, DRZ}));
  EXPECT_EQ(parseComponents("DZ"), (std::vector<int>{DZ}));
  EXPECT_TRUE(parseComponents("").empty());
  EXPECT_TRUE(parseComponents(" , ").empty());
}

TEST(Components, ParsesGroups) {
  EXPECT_EQ(parseComponents("all"), (std::vector<int>{DX, DY, DZ, DRX, DRY, DRZ}));
  EXPECT_EQ(parseComponents("ALL"), (std::vector<int>{DX, DY, DZ, DRX, DRY, DRZ}));
  EXPECT_EQ(parseComponents("Translations"), (std::vector<int>{DX, DY, DZ}));
  EXPECT_EQ(parseComponents("rotations"), (std::vector<int>{DRX, DRY, DRZ}));
  EXPECT_EQ(parseComponents("rotations, DY dx"), (std::vector<int>{DX, DY, DRX, DRY, DRZ}));
  EXPECT_EQ(parseComponents("translations rotations"),
            (std::vector<int>{DX, DY, DZ, DRX, DRY, DRZ}));
}

TEST(Components, BadTokenIsNamedWithValidList) {
  try {
    parseComponents("DX, Dq DZ");
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'Dq'"), std::string::npos) << what;
    for (const char* valid : {"DX", "DY", "DZ", "DRX", "DRY", "DRZ", "ALL", "TRANSLATIONS"})
      EXPECT_NE(what.find(valid), std::string::npos) << what;
  }
  EXPECT_THROW(parseComponents("DX;DY"), std::invalid_argument);
  EXPECT_THROW(parseComponents("every"), std::invalid_argument);
}
