#include "input/XmlInput.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include <Teuchos_StringInputSource.hpp>
#include <Teuchos_XMLObject.hpp>
#include <Teuchos_XMLParameterListHelpers.hpp>

#include "core/Errors.hpp"

namespace choc {

namespace {
// A Teuchos exception reads "<source>:<line>:", "Throw number = N", "Throw test that evaluated
// to true: ...", then the message: keep the message (the last non-blank line).
std::string teuchosMessage(const std::string& s) {
  std::string line, last;
  std::istringstream in(s);
  while (std::getline(in, line))
    if (line.find_first_not_of(" \t\r") != std::string::npos) last = line;
  return last.empty() ? s : last;
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

// Whole-string number checks: Teuchos reads "7800kg" as 7800 and "abc" as 0 without a word.
bool isDouble(const std::string& v) {
  const char* b = v.c_str();
  char* end = nullptr;
  std::strtod(b, &end);
  if (end == b) return false;
  while (*end == ' ' || *end == '\t') ++end;
  return *end == '\0';
}

bool isInt(const std::string& v) {
  const char* b = v.c_str();
  char* end = nullptr;
  errno = 0;
  const long long x = std::strtoll(b, &end, 10);
  if (end == b || errno == ERANGE || x < INT_MIN || x > INT_MAX) return false;
  while (*end == ' ' || *end == '\t') ++end;
  return *end == '\0';
}

// Checks what Teuchos accepts silently or reports without the parameter's name: a value that
// is not a number of its declared type, a bool that is not true/false, a type choc does not
// use, a missing attribute, a name given twice in one list (Teuchos keeps the last one).
void checkEntries(const Teuchos::XMLObject& list, const std::string& path,
                  const std::string& file) {
  std::set<std::string> seen;
  for (int i = 0; i < list.numChildren(); ++i) {
    const Teuchos::XMLObject& c = list.getChild(i);
    const std::string& tag = c.getTag();
    if (tag != "Parameter" && tag != "ParameterList") continue;
    if (!c.hasAttribute("name"))
      throwInput(file, path.empty() ? std::string("(top level)") : path, "",
                 "a <" + tag + "> has no name attribute", "add name=\"...\"");
    const std::string& name = c.getAttribute("name");
    const std::string param = path.empty() ? name : path + "/" + name;
    if (!seen.insert(name).second)
      throwInput(file, param, "", "is given twice in the same list", "keep only one");
    if (tag == "ParameterList") {
      checkEntries(c, param, file);
      continue;
    }
    if (!c.hasAttribute("type") || !c.hasAttribute("value"))
      throwInput(file, param, "", "needs both a type and a value attribute",
                 "write e.g. <Parameter name=\"" + name + "\" type=\"double\" value=\"1\"/>");
    const std::string& type = c.getAttribute("type");
    const std::string& value = c.getAttribute("value");
    if (type == "double") {
      if (!isDouble(value))
        throwInput(file, param, value, "is not a number", "write a number, e.g. 7800 or 2e11");
    } else if (type == "int") {
      if (!isInt(value))
        throwInput(file, param, value, "is not an integer", "write a whole number, e.g. 40");
    } else if (type == "bool") {
      const std::string u = upper(value);
      if (u != "TRUE" && u != "FALSE" && u != "YES" && u != "NO" && u != "1" && u != "0")
        throwInput(file, param, value, "is not a bool", "write true or false");
    } else if (type != "string") {
      throwInput(file, param, "", "unknown type '" + type + "'",
                 "use type=\"double\", \"int\", \"bool\" or \"string\"");
    }
  }
}
}  // namespace

Teuchos::RCP<Teuchos::ParameterList> readXmlParameters(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec))
    throwInput(path, "", "", "input file not found", "check the path");
  if (fs::is_directory(path, ec)) throwInput(path, "", "", "is a directory, not an input file");
  std::ifstream probe(path);
  if (!probe) throwInput(path, "", "", "cannot be read (permissions?)");
  std::string content((std::istreambuf_iterator<char>(probe)), std::istreambuf_iterator<char>());
  if (content.find_first_not_of(" \t\r\n") == std::string::npos)
    throwInput(path, "", "", "input file is empty",
               "it must hold a <ParameterList> (see input/sdnl111a.xml)");
  Teuchos::XMLObject xml;
  try {
    xml = Teuchos::StringInputSource(content).getObject();
  } catch (const std::exception& e) {
    throwInput(path, "", "", "malformed XML: " + teuchosMessage(e.what()), "fix the XML");
  }
  if (xml.getTag() == "ParameterList") checkEntries(xml, "", path);
  try {
    return Teuchos::getParametersFromXmlString(content);
  } catch (const std::exception& e) {
    throwInput(path, "", "", "malformed XML parameter list: " + teuchosMessage(e.what()),
               "fix the XML (each value needs name, type and value attributes)");
  }
}

std::string resolveBeside(const std::string& inputFile, const std::string& relative) {
  namespace fs = std::filesystem;
  fs::path p(relative);
  if (p.is_absolute()) return relative;
  return (fs::path(inputFile).parent_path() / p).lexically_normal().string();
}

}  // namespace choc
