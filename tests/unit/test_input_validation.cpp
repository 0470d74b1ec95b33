// The parameter validation every input sublist goes through: defaults, types, ranges,
// choices, required keys, unknown keys with the closest suggestion, named sublists.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include "core/Errors.hpp"
#include "input/ParameterSpec.hpp"
#include "input/Validation.hpp"
#include "input/Vector3.hpp"

namespace choc {
namespace {

Teuchos::ParameterList spec() {
  Teuchos::ParameterList p;
  declareDouble(p, "Time Step", 1e-6, "dt", Range::positive());
  declareInt(p, "Modes", 10, "count", Range::atLeast(1));
  declareBool(p, "Write", true, "write files");
  declareChoice(p, "Scheme", "euler", {"euler", "central"}, "scheme");
  declareRequiredString(p, "Mesh", "mesh file");
  ParameterList& mats = declareNamedSublists(p, "Materials", "materials");
  declareRequiredDouble(mats, "Density", "rho", Range::positive());
  declareDouble(mats, "Poisson's Ratio", 0.0, "nu", {-1.0, 0.5, true, true});
  declareOpenSublist(p, "Analyses", "validated by their owner");
  return p;
}

std::string messageOf(Teuchos::ParameterList user) {
  try {
    validate(user, spec(), InputLocation{"in.xml", ""});
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Validation, FillsDefaultsAndAcceptsAnIntegerWhereADoubleIsExpected) {
  Teuchos::ParameterList user;
  user.set("Mesh", std::string("m.exo"));
  user.set("Time Step", 2);  // written as an int
  user.sublist("Materials").sublist("steel").set("Density", 7800.0);
  validate(user, spec(), InputLocation{"in.xml", ""});
  EXPECT_DOUBLE_EQ(user.get<double>("Time Step"), 2.0);
  EXPECT_EQ(user.get<int>("Modes"), 10);
  EXPECT_TRUE(user.get<bool>("Write"));
  EXPECT_EQ(user.get<std::string>("Scheme"), "euler");
  EXPECT_DOUBLE_EQ(user.sublist("Materials").sublist("steel").get<double>("Poisson's Ratio"), 0.0);
}

TEST(Validation, UnknownKeySuggestsTheClosestOneWithFileAndPath) {
  Teuchos::ParameterList user;
  user.set("Mesh", std::string("m.exo"));
  user.sublist("Materials").sublist("steel").set("Densty", 7800.0);
  const std::string m = messageOf(user);
  EXPECT_NE(m.find("in.xml"), std::string::npos) << m;
  EXPECT_NE(m.find("Materials/steel/Densty"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'Density'"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos);
}

TEST(Validation, RejectsWrongTypesRangesChoicesAndMissingKeys) {
  Teuchos::ParameterList base;
  base.set("Mesh", std::string("m.exo"));
  {
    auto u = base;
    u.set("Time Step", std::string("fast"));
    EXPECT_NE(messageOf(u).find("expected double"), std::string::npos);
  }
  {
    auto u = base;
    u.set("Time Step", 0.0);  // (0, inf)
    const std::string m = messageOf(u);
    EXPECT_NE(m.find("out of range"), std::string::npos) << m;
    EXPECT_NE(m.find("(0, inf"), std::string::npos) << m;
  }
  {
    auto u = base;
    u.set("Scheme", std::string("centrall"));
    EXPECT_NE(messageOf(u).find("did you mean 'central'"), std::string::npos);
  }
  {
    auto u = base;
    u.sublist("Materials").sublist("steel").set("Poisson's Ratio", 0.5);  // open at 0.5
    u.sublist("Materials").sublist("steel").set("Density", 1.0);
    EXPECT_NE(messageOf(u).find("Poisson's Ratio"), std::string::npos);
  }
  {
    Teuchos::ParameterList u;  // Mesh missing
    EXPECT_NE(messageOf(u).find("required but missing"), std::string::npos);
  }
  {
    auto u = base;
    u.set("Materials", 3.0);  // a value where a sublist is expected
    EXPECT_NE(messageOf(u).find("must be a sublist"), std::string::npos);
  }
}

TEST(Validation, OpenSublistsAreLeftToTheirOwner) {
  Teuchos::ParameterList user;
  user.set("Mesh", std::string("m.exo"));
  user.sublist("Analyses").sublist("run").set("Anything", 1);
  EXPECT_EQ(messageOf(user), "");
}

TEST(Validation, ClosestNameOnlySuggestsCloseNames) {
  EXPECT_EQ(closestName("densty", {"Density", "Mass"}), "Density");
  EXPECT_EQ(closestName("completely different", {"Density", "Mass"}), "");
}

TEST(Vector3, ParsesThreeNumbersAndRejectsTheRest) {
  const auto v = parseVector3(" 0 1  -2.5 ", "f.xml", "Axis");
  EXPECT_EQ(v[2], -2.5);
  EXPECT_THROW(parseVector3("0 1", "f.xml", "Axis"), InputError);
  EXPECT_THROW(parseVector3("0 1 2 3", "f.xml", "Axis"), InputError);
  EXPECT_THROW(parseVector3("0 y 2", "f.xml", "Axis"), InputError);
}

TEST(Errors, OneLineMessageNamesFileParameterValueAndFix) {
  const std::string m = inputMessage("in.xml", "A/B", "3", "too big\nreally", "use 2");
  EXPECT_EQ(m, "in.xml: parameter 'A/B' = '3': too big really; use 2");
}

}  // namespace
}  // namespace choc
