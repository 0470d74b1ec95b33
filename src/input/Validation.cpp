#include "input/Validation.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <ostream>
#include <sstream>

#include "core/Errors.hpp"
#include "input/OutputName.hpp"
#include "input/ParameterSpec.hpp"

namespace choc {

namespace {


std::vector<std::string> visibleNames(const ParameterList& valid) {
  std::vector<std::string> names;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& n = valid.name(it);
    if (!n.empty() && n[0] == '*') continue;
    names.push_back(n);
  }
  return names;
}

const SpecValidator* specOf(const Teuchos::ParameterEntry& e) {
  return dynamic_cast<const SpecValidator*>(e.validator().get());
}

std::string userTypeName(const Teuchos::ParameterEntry& e) {
  if (e.isList()) return "sublist";
  if (e.isType<double>()) return "double";
  if (e.isType<int>()) return "int";
  if (e.isType<bool>()) return "bool";
  if (e.isType<std::string>()) return "string";
  return e.getAny(false).typeName();
}

void checkValue(ParameterList& user, const std::string& name, const SpecValidator& spec,
                const InputLocation& where) {
  Teuchos::ParameterEntry& e = user.getEntry(name);
  const std::string param = where.parameter(name);
  const std::string value = entryToString(e);
  using Kind = SpecValidator::Kind;
  switch (spec.kind()) {
    case Kind::Double: {
      double v;
      if (e.isType<double>()) v = Teuchos::getValue<double>(e);
      else if (e.isType<int>()) {
        v = Teuchos::getValue<int>(e);
        user.set(name, v);  // an integer written where a double is expected is fine
      } else {
        throwInput(where.file, param, value, "has type " + userTypeName(e) + ", expected double",
                   "write type=\"double\"");
      }
      if (!std::isfinite(v) || !spec.range().contains(v))
        throwInput(where.file, param, value, "out of range", "valid: " + spec.describe());
      break;
    }
    case Kind::Int: {
      if (!e.isType<int>())
        throwInput(where.file, param, value, "has type " + userTypeName(e) + ", expected int",
                   "write type=\"int\"");
      if (!spec.range().contains(Teuchos::getValue<int>(e)))
        throwInput(where.file, param, value, "out of range", "valid: " + spec.describe());
      break;
    }
    case Kind::Bool:
      if (!e.isType<bool>())
        throwInput(where.file, param, value, "has type " + userTypeName(e) + ", expected bool",
                   "write type=\"bool\" value=\"true\" or \"false\"");
      break;
    case Kind::String:
      if (!e.isType<std::string>())
        throwInput(where.file, param, value, "has type " + userTypeName(e) + ", expected string",
                   "write type=\"string\"");
      if (spec.required() && Teuchos::getValue<std::string>(e).empty())
        throwInput(where.file, param, value, "must not be empty");
      break;
    case Kind::Choice: {
      if (!e.isType<std::string>())
        throwInput(where.file, param, value, "has type " + userTypeName(e) + ", expected string",
                   "valid: " + spec.describe());
      const std::string v = Teuchos::getValue<std::string>(e);
      const auto& c = spec.choices();
      if (std::find(c.begin(), c.end(), v) == c.end()) {
        throwInput(where.file, param, v, "is not a valid choice",
                   didYouMean(v, c) +
                       "valid: " + spec.describe());
      }
      break;
    }
  }
}

}  // namespace


std::string entryToString(const Teuchos::ParameterEntry& e) {
  if (e.isList()) return "<sublist>";
  std::ostringstream s;
  if (e.isType<double>()) s << Teuchos::getValue<double>(e);
  else if (e.isType<int>()) s << Teuchos::getValue<int>(e);
  else if (e.isType<bool>()) s << (Teuchos::getValue<bool>(e) ? "true" : "false");
  else if (e.isType<std::string>()) s << Teuchos::getValue<std::string>(e);
  else s << e.getAny(false);
  return s.str();
}

void validate(ParameterList& user, const ParameterList& valid, const InputLocation& where) {
  const bool named = isNamedSublists(valid);
  const bool open = isOpenSublist(valid);
  // 1. Every user key must be known and well formed.
  std::vector<std::string> userNames;
  for (auto it = user.begin(); it != user.end(); ++it) userNames.push_back(user.name(it));
  for (const std::string& name : userNames) {
    const Teuchos::ParameterEntry& ue = user.getEntry(name);
    if (named || open) {
      if (!ue.isList())
        throwInput(where.file, where.parameter(name), entryToString(ue),
                   "is a parameter where a sublist is expected",
                   "each entry of '" + where.path + "' is a <ParameterList name=...>");
      if (named && namesAreOutputNames(valid)) checkOutputName(where.file, where.path, name);
      if (named) validate(user.sublist(name), namedSublistTemplate(valid), where.child(name));
      continue;
    }
    const Teuchos::ParameterEntry* ve = valid.getEntryPtr(name);
    if (!ve || (!name.empty() && name[0] == '*')) {
      const std::string near = closestName(name, visibleNames(valid));
      throwInput(where.file, where.parameter(name), "", "unknown parameter",
                 near.empty() ? "valid keys here: see 'choc parameters'"
                              : "did you mean '" + near + "'?");
    }
    if (ve->isList()) {
      if (!ue.isList())
        throwInput(where.file, where.parameter(name), entryToString(ue),
                   "must be a sublist (<ParameterList name=\"" + name + "\">)");
      validate(user.sublist(name), valid.sublist(name), where.child(name));
      continue;
    }
    if (ue.isList())
      throwInput(where.file, where.parameter(name), "", "is a sublist where a parameter is expected");
    if (const SpecValidator* spec = specOf(*ve)) checkValue(user, name, *spec, where);
  }
  if (named || open) return;
  // 2. Missing keys: required ones are errors, the others take their defaults.
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (name.empty() || name[0] == '*' || user.isParameter(name)) continue;
    const Teuchos::ParameterEntry& ve = valid.entry(it);
    if (ve.isList()) {
      ParameterList& created = user.sublist(name);
      validate(created, valid.sublist(name), where.child(name));
      continue;
    }
    const SpecValidator* spec = specOf(ve);
    if (spec && spec->required())
      throwInput(where.file, where.parameter(name), "", "is required but missing",
                 "add it (" + spec->describe() + ")");
    user.setEntry(name, Teuchos::ParameterEntry(ve.getAny(false), true, false));  // isDefault: not given
    user.getEntry(name).setDocString(ve.docString());
  }
}

void printValidParameters(std::ostream& out, const ParameterList& valid,
                          const std::string& indent) {
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    const Teuchos::ParameterEntry& e = valid.entry(it);
    if (name == "*open*" || name == "*output names*") continue;
    if (e.isList()) {
      const ParameterList& sub = valid.sublist(name);
      if (name == "*") {
        out << indent << "<any name>/  " << e.docString() << "\n";
        printValidParameters(out, sub, indent + "  ");
        continue;
      }
      out << indent << name << "/  " << e.docString() << "\n";
      if (isOpenSublist(sub))
        out << indent << "  <any name>/  (keys depend on the entry; see below)\n";
      printValidParameters(out, sub, indent + "  ");
      continue;
    }
    const SpecValidator* spec = specOf(e);
    out << indent << name;
    if (spec) {
      out << " (" << spec->typeName();
      if (spec->required()) out << ", required";
      else out << ", default " << (spec->kind() == SpecValidator::Kind::String ||
                                           spec->kind() == SpecValidator::Kind::Choice
                                       ? "'" + entryToString(e) + "'"
                                       : entryToString(e));
      out << "; " << spec->describe() << ")";
    }
    out << "\n" << indent << "    " << e.docString() << "\n";
  }
}

namespace {

// One markdown table row: the cells of a key or of a sublist.
struct MarkdownRow {
  std::string key, type, def, valid, doc;
};

// Text safe in a markdown table cell or paragraph: one line; '|' does not end the cell, '<'
// opens no HTML tag, '*' no emphasis.
std::string markdownText(const std::string& text) {
  std::string s;
  for (char c : text) {
    if (c == '\n' || c == '\r') c = ' ';
    if (c == '|' || c == '<' || c == '*' || c == '\\' || c == '`') s += '\\';
    s += c;
  }
  return s;
}

std::string childPath(const std::string& path, const std::string& name) {
  return path.empty() ? name : path + "/" + name;
}

bool isMarker(const std::string& name) {
  return name == "*open*" || name == "*output names*";
}

std::string defaultText(const Teuchos::ParameterEntry& e, const SpecValidator* spec) {
  if (spec && spec->required()) return "required";
  if (e.isType<std::string>()) return "'" + entryToString(e) + "'";
  return entryToString(e);
}

MarkdownRow keyRow(const std::string& name, const Teuchos::ParameterEntry& e) {
  const SpecValidator* spec = specOf(e);
  return {name, spec ? spec->typeName() : userTypeName(e), defaultText(e, spec),
          spec ? spec->describe() : "", e.docString()};
}

MarkdownRow sublistRow(const std::string& path, const std::string& name,
                       const Teuchos::ParameterEntry& e, const ParameterList& sub) {
  const std::string p = childPath(path, name);
  if (isOpenSublist(sub))
    return {name, "sublists", "",
            "one sublist per entry, named by the user; its keys depend on its 'Type': see the "
            "sections '" + name + "/<name> (Type = ...)'",
            e.docString()};
  if (isNamedSublists(sub)) {
    std::string valid = "one sublist per entry, named by the user: see the section '" + p +
                        "/<any name>'";
    if (namesAreOutputNames(sub)) valid += "; names: " + outputNameRule();
    return {name, "sublists", "", valid, e.docString()};
  }
  return {name, "sublist", "", "see the section '" + p + "'", e.docString()};
}

void printMarkdownTable(std::ostream& out, const std::vector<MarkdownRow>& rows) {
  out << "| key | type | default | valid values | documentation |\n"
      << "|---|---|---|---|---|\n";
  for (const MarkdownRow& r : rows)
    out << "| " << markdownText(r.key) << " | " << r.type << " | " << markdownText(r.def)
        << " | " << markdownText(r.valid) << " | " << markdownText(r.doc) << " |\n";
}

std::vector<MarkdownRow> markdownRows(const ParameterList& valid, const std::string& path) {
  std::vector<MarkdownRow> rows;
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    const Teuchos::ParameterEntry& e = valid.entry(it);
    if (isMarker(name)) continue;
    rows.push_back(e.isList() ? sublistRow(path, name, e, valid.sublist(name)) : keyRow(name, e));
  }
  return rows;
}

}  // namespace

void printValidParametersMarkdown(std::ostream& out, const ParameterList& valid,
                                  const std::string& path, const std::string& doc) {
  out << "\n### " << (path.empty() ? std::string("(top level)") : "`" + path + "`") << "\n\n";
  if (!doc.empty()) out << markdownText(doc) << "\n\n";
  const std::vector<MarkdownRow> rows = markdownRows(valid, path);
  if (rows.empty()) out << "No keys.\n";
  else printMarkdownTable(out, rows);
  for (auto it = valid.begin(); it != valid.end(); ++it) {
    const std::string& name = valid.name(it);
    if (isMarker(name) || !valid.entry(it).isList()) continue;
    const ParameterList& sub = valid.sublist(name);
    const std::string& subDoc = valid.entry(it).docString();
    if (isOpenSublist(sub)) continue;
    if (isNamedSublists(sub))
      printValidParametersMarkdown(out, namedSublistTemplate(sub),
                                   childPath(path, name) + "/<any name>", subDoc);
    else
      printValidParametersMarkdown(out, sub, childPath(path, name), subDoc);
  }
}

}  // namespace choc
