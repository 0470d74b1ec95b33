#include "input/ParameterSpec.hpp"

#include <cmath>
#include <sstream>

#include <Teuchos_RCP.hpp>

#include "core/Format.hpp"

namespace choc {

namespace {
const char* kTemplate = "*";
const char* kOpenMarker = "*open*";
const char* kOutputNamesMarker = "*output names*";


void attach(ParameterList& pl, const std::string& name, const Teuchos::ParameterEntry& value,
            const std::string& doc, Teuchos::RCP<SpecValidator> validator) {
  pl.setEntry(name, value);
  Teuchos::ParameterEntry& e = pl.getEntry(name);
  e.setDocString(doc);
  e.setValidator(validator);
}

Teuchos::RCP<SpecValidator> makeValidator(SpecValidator::Kind kind, Range r = Range::any(),
                                          std::vector<std::string> choices = {},
                                          bool required = false) {
  return Teuchos::rcp(new SpecValidator(kind, r, std::move(choices), required));
}
}  // namespace

bool Range::contains(double v) const {
  if (std::isnan(v)) return false;
  if (loOpen ? !(v > lo) : !(v >= lo)) return false;
  if (hiOpen ? !(v < hi) : !(v <= hi)) return false;
  return true;
}

std::string Range::describe() const {
  // An infinite end is never attained: always an open bracket.
  return std::string(loOpen || std::isinf(lo) ? "(" : "[") + shortNumber(lo) + ", " + shortNumber(hi) +
         (hiOpen || std::isinf(hi) ? ")" : "]");
}

SpecValidator::SpecValidator(Kind kind, Range range, std::vector<std::string> choices,
                             bool required)
    : kind_(kind), range_(range), choices_(std::move(choices)), required_(required) {}

std::string SpecValidator::typeName() const {
  switch (kind_) {
    case Kind::Double: return "double";
    case Kind::Int: return "int";
    case Kind::Bool: return "bool";
    default: return "string";
  }
}

std::string SpecValidator::describe() const {
  switch (kind_) {
    case Kind::Double:
    case Kind::Int: return "a" + std::string(kind_ == Kind::Int ? "n integer" : " number") +
                           " in " + range_.describe();
    case Kind::Bool: return "true or false";
    case Kind::Choice: {
      std::string s = "one of ";
      for (size_t i = 0; i < choices_.size(); ++i) s += (i ? ", " : "") + ("'" + choices_[i] + "'");
      return s;
    }
    default: return "a string";
  }
}

void SpecValidator::printDoc(const std::string& docString, std::ostream& out) const {
  out << "# " << docString << " (" << typeName() << "; " << describe()
      << (required_ ? "; required" : "") << ")\n";
}

Teuchos::ParameterEntryValidator::ValidStringsList SpecValidator::validStringValues() const {
  if (kind_ != Kind::Choice) return Teuchos::null;
  return Teuchos::rcp(new Teuchos::Array<std::string>(choices_.begin(), choices_.end()));
}

void SpecValidator::validate(const Teuchos::ParameterEntry&, const std::string&,
                             const std::string&) const {
  // choc validates in Validation.cpp, where the file and path are known.
}

void declareDouble(ParameterList& pl, const std::string& name, double def, const std::string& doc,
                   Range range) {
  attach(pl, name, Teuchos::ParameterEntry(def), doc,
         makeValidator(SpecValidator::Kind::Double, range));
}
void declareRequiredDouble(ParameterList& pl, const std::string& name, const std::string& doc,
                           Range range) {
  attach(pl, name, Teuchos::ParameterEntry(0.0), doc,
         makeValidator(SpecValidator::Kind::Double, range, {}, true));
}
void declareInt(ParameterList& pl, const std::string& name, int def, const std::string& doc,
                Range range) {
  attach(pl, name, Teuchos::ParameterEntry(def), doc,
         makeValidator(SpecValidator::Kind::Int, range));
}
void declareBool(ParameterList& pl, const std::string& name, bool def, const std::string& doc) {
  attach(pl, name, Teuchos::ParameterEntry(def), doc, makeValidator(SpecValidator::Kind::Bool));
}
void declareString(ParameterList& pl, const std::string& name, const std::string& def,
                   const std::string& doc) {
  attach(pl, name, Teuchos::ParameterEntry(def), doc, makeValidator(SpecValidator::Kind::String));
}
void declareRequiredString(ParameterList& pl, const std::string& name, const std::string& doc) {
  attach(pl, name, Teuchos::ParameterEntry(std::string()), doc,
         makeValidator(SpecValidator::Kind::String, Range::any(), {}, true));
}
void declareChoice(ParameterList& pl, const std::string& name, const std::string& def,
                   const std::vector<std::string>& choices, const std::string& doc) {
  attach(pl, name, Teuchos::ParameterEntry(def), doc,
         makeValidator(SpecValidator::Kind::Choice, Range::any(), choices));
}
void declareRequiredChoice(ParameterList& pl, const std::string& name,
                           const std::vector<std::string>& choices, const std::string& doc) {
  attach(pl, name, Teuchos::ParameterEntry(std::string()), doc,
         makeValidator(SpecValidator::Kind::Choice, Range::any(), choices, true));
}

ParameterList& declareSublist(ParameterList& pl, const std::string& name, const std::string& doc) {
  return pl.sublist(name, false, doc);
}

ParameterList& declareNamedSublists(ParameterList& pl, const std::string& name,
                                    const std::string& doc, NamedAs names) {
  ParameterList& s = pl.sublist(name, false, doc);
  if (names == NamedAs::OutputName) s.set(kOutputNamesMarker, true);
  return s.sublist(kTemplate, false, "template for each user-named sublist");
}

void declareOpenSublist(ParameterList& pl, const std::string& name, const std::string& doc) {
  ParameterList& s = pl.sublist(name, false, doc);
  s.set(kOpenMarker, true);
}

bool isNamedSublists(const ParameterList& valid) { return valid.isSublist(kTemplate); }
const ParameterList& namedSublistTemplate(const ParameterList& valid) {
  return valid.sublist(kTemplate);
}
bool isOpenSublist(const ParameterList& valid) { return valid.isParameter(kOpenMarker); }
bool namesAreOutputNames(const ParameterList& valid) { return valid.isParameter(kOutputNamesMarker); }

}  // namespace choc
