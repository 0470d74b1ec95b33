// Declaring valid parameters: every key gets a default (or is required), a documentation
// string and a validator (range or choice). The owners of input sublists build their valid
// lists with these functions; validate() in Validation.hpp checks user input against them.
#pragma once
#include <limits>
#include <string>
#include <vector>

#include <Teuchos_ParameterEntryValidator.hpp>
#include <Teuchos_ParameterList.hpp>

namespace choc {

using Teuchos::ParameterList;

// A numeric interval; open or closed at each end.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool loOpen = false, hiOpen = false;
  static Range any() { return {}; }
  static Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, false}; }
  static Range nonNegative() { return {0.0, std::numeric_limits<double>::infinity(), false, false}; }
  static Range closed(double a, double b) { return {a, b, false, false}; }
  static Range atLeast(double a) { return {a, std::numeric_limits<double>::infinity(), false, false}; }
  bool contains(double v) const;
  std::string describe() const;  // e.g. "(0, inf)" or "[-0.333333, 0]"
};

// The validator attached to every declared parameter.
class SpecValidator : public Teuchos::ParameterEntryValidator {
 public:
  enum class Kind { Double, Int, Bool, String, Choice };
  SpecValidator(Kind kind, Range range, std::vector<std::string> choices, bool required);
  Kind kind() const { return kind_; }
  const Range& range() const { return range_; }
  const std::vector<std::string>& choices() const { return choices_; }
  bool required() const { return required_; }
  std::string typeName() const;  // "double", "int", "bool", "string"
  std::string describe() const;  // valid values in words

  // Teuchos interface
  const std::string getXMLTypeName() const override { return "chocSpecValidator"; }
  void printDoc(const std::string& docString, std::ostream& out) const override;
  ValidStringsList validStringValues() const override;
  void validate(const Teuchos::ParameterEntry& entry, const std::string& paramName,
                const std::string& sublistName) const override;

 private:
  Kind kind_;
  Range range_;
  std::vector<std::string> choices_;
  bool required_;
};

void declareDouble(ParameterList& pl, const std::string& name, double def, const std::string& doc,
                   Range range = Range::any());
void declareRequiredDouble(ParameterList& pl, const std::string& name, const std::string& doc,
                           Range range = Range::any());
void declareInt(ParameterList& pl, const std::string& name, int def, const std::string& doc,
                Range range = Range::any());
void declareBool(ParameterList& pl, const std::string& name, bool def, const std::string& doc);
void declareString(ParameterList& pl, const std::string& name, const std::string& def,
                   const std::string& doc);
void declareRequiredString(ParameterList& pl, const std::string& name, const std::string& doc);
void declareChoice(ParameterList& pl, const std::string& name, const std::string& def,
                   const std::vector<std::string>& choices, const std::string& doc);
void declareRequiredChoice(ParameterList& pl, const std::string& name,
                           const std::vector<std::string>& choices, const std::string& doc);

// A sublist with fixed keys (validated recursively). Returns it for declaring its keys.
ParameterList& declareSublist(ParameterList& pl, const std::string& name, const std::string& doc);
// A sublist whose children are user-named sublists, each validated against the returned
// template (e.g. Materials/<any name>). With NamedAs::OutputName the names become file names
// or result columns and must follow the rule of input/OutputName.hpp.
enum class NamedAs { Anything, OutputName };
ParameterList& declareNamedSublists(ParameterList& pl, const std::string& name,
                                    const std::string& doc, NamedAs names = NamedAs::Anything);
// A sublist whose children are user-named sublists validated by their owner later (e.g.
// Analyses/<name>, whose keys depend on its Type).
void declareOpenSublist(ParameterList& pl, const std::string& name, const std::string& doc);

bool isNamedSublists(const ParameterList& valid);
const ParameterList& namedSublistTemplate(const ParameterList& valid);
bool isOpenSublist(const ParameterList& valid);
bool namesAreOutputNames(const ParameterList& valid);

}  // namespace choc
