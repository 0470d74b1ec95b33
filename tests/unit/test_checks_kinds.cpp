// The kinds of the 'Checks' entries: the default type, unknown types, and the translation of
// the 'Exact Solution' sublist of the previous release.
#include <gtest/gtest.h>

#include <string>

#include "checks/HistoryCheck.hpp"
#include "core/Errors.hpp"

namespace choc {
namespace {

Teuchos::ParameterList valueRow() {
  Teuchos::ParameterList row;
  row.set("Quantity", std::string("A:DX"));
  row.set("Time", 4e-4);
  row.set("Reference", -1.55e-4);
  row.set("Tolerance", 0.035);
  return row;
}

TEST(CheckKinds, AnEntryWithoutTypeIsAValueRow) {
  Teuchos::ParameterList checks;
  checks.set("row", valueRow());
  validateChecks(checks, InputLocation{"in.xml", "Analyses/a/Checks"});
  const auto& row = checks.sublist("row");
  EXPECT_EQ(row.get<std::string>("Type"), "Value");
  EXPECT_EQ(row.get<std::string>("Criterion"), "relative");  // defaults filled in
  EXPECT_EQ(row.get<std::string>("Kind"), "analytic");
}

TEST(CheckKinds, UnknownTypeNamesTheClosestKind) {
  Teuchos::ParameterList checks;
  Teuchos::ParameterList row;
  row.set("Type", std::string("Bar Impact Exact"));
  checks.set("exact", row);
  try {
    validateChecks(checks, InputLocation{"in.xml", "Analyses/a/Checks"});
    FAIL() << "an unknown check type was accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("in.xml: parameter 'Analyses/a/Checks/exact/Type' = 'Bar Impact Exact': unknown check type"),
              std::string::npos) << m;
    EXPECT_NE(m.find("did you mean 'Bar Impact Exact Solution'?"), std::string::npos) << m;
  }
}

TEST(CheckKinds, KeysOfAnotherKindAreRefused) {
  Teuchos::ParameterList checks;
  Teuchos::ParameterList row = valueRow();
  row.set("Wave Speed", std::string("bar"));  // a key of the exact-solution check
  checks.set("row", row);
  EXPECT_THROW(validateChecks(checks, InputLocation{"in.xml", "Analyses/a/Checks"}), InputError);
}

TEST(CheckKinds, DeprecatedExactSolutionBecomesTheLastCheck) {
  Teuchos::ParameterList a;
  a.sublist("Checks").set("row", valueRow());
  Teuchos::ParameterList& old = a.sublist("Exact Solution");
  old.set("Enabled", true);
  old.set("Node Set", std::string("N1"));
  translateDeprecatedExactSolution(a, "in.xml", "Analyses/a");
  EXPECT_FALSE(a.isSublist("Exact Solution"));
  const Teuchos::ParameterList& checks = a.sublist("Checks");
  ASSERT_TRUE(checks.isSublist("exact solution"));
  EXPECT_EQ(checks.name(checks.begin()), "row");  // the document's rows stay first
  const auto& e = checks.sublist("exact solution");
  EXPECT_EQ(e.get<std::string>("Type"), "Bar Impact Exact Solution");
  EXPECT_EQ(e.get<std::string>("Node Set"), "N1");
  EXPECT_FALSE(e.isParameter("Enabled"));
  validateChecks(a.sublist("Checks"), InputLocation{"in.xml", "Analyses/a/Checks"});
}

TEST(CheckKinds, DisabledDeprecatedExactSolutionIsDropped) {
  Teuchos::ParameterList a;
  a.sublist("Exact Solution").set("Enabled", false);
  translateDeprecatedExactSolution(a, "in.xml", "Analyses/a");
  EXPECT_FALSE(a.isSublist("Exact Solution"));
  EXPECT_FALSE(a.isSublist("Checks"));
}

}  // namespace
}  // namespace choc
