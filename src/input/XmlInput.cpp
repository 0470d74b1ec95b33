#include "input/XmlInput.hpp"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cstdlib>
#include <cstring>
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
  double x = 0;
  return parseDecimal(v, x);
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
// Limits on what an input may hold, checked before any XML parser sees it: the parsers and the
// validation recurse into nested lists, and an input of 10,000 nested lists overflowed the
// stack. Real inputs are a few kB deep by a few levels.
constexpr std::size_t kMaxInputBytes = 16u << 20;
constexpr int kMaxNesting = 64;
constexpr long kMaxElements = 200000;

// Walks the tags (skipping comments, CDATA, processing instructions and declarations) and
// refuses an input nested deeper or holding more elements than the limits.
void checkInputShape(const std::string& text, const std::string& path) {
  int depth = 0;
  long elements = 0;
  std::size_t i = 0;
  const auto skipTo = [&](const char* end) {
    const std::size_t at = text.find(end, i);
    i = at == std::string::npos ? text.size() : at + std::strlen(end);
  };
  while ((i = text.find('<', i)) != std::string::npos) {
    if (text.compare(i, 4, "<!--") == 0) { skipTo("-->"); continue; }
    if (text.compare(i, 9, "<![CDATA[") == 0) { skipTo("]]>"); continue; }
    if (text.compare(i, 2, "<?") == 0) { skipTo("?>"); continue; }
    if (text.compare(i, 2, "<!") == 0) { skipTo(">"); continue; }
    const bool closing = text.compare(i, 2, "</") == 0;
    char quote = 0;
    std::size_t j = i + 1;
    for (; j < text.size() && (quote || text[j] != '>'); ++j)
      if (text[j] == '"' || text[j] == '\'') quote = quote == text[j] ? 0 : quote ? quote : text[j];
    const bool selfClosing = j < text.size() && text[j - 1] == '/';
    i = j;
    if (closing) {
      --depth;
      continue;
    }
    if (++elements > kMaxElements)
      throwInput(path, "", "", "holds more than " + std::to_string(kMaxElements) + " XML elements",
                 "an input describes a model in at most a few thousand; check the file");
    if (!selfClosing && ++depth > kMaxNesting)
      throwInput(path, "", "", "nests lists more than " + std::to_string(kMaxNesting) + " levels deep",
                 "an input is a few levels deep (Analyses/<name>/Contact/Pairs/<pair>); check the file");
  }
}

}  // namespace

bool parseDecimal(const std::string& token, double& value) {
  if (token.find_first_of("xX") != std::string::npos) return false;  // no hexadecimal input
  const char* b = token.c_str();
  char* end = nullptr;
  value = std::strtod(b, &end);
  if (end == b) return false;
  while (*end == ' ' || *end == '\t') ++end;
  return *end == '\0';
}

Teuchos::RCP<Teuchos::ParameterList> readXmlParameters(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists(path, ec))
    throwInput(path, "", "", "input file not found", "check the path");
  if (fs::is_directory(path, ec)) throwInput(path, "", "", "is a directory, not an input file");
  const std::uintmax_t bytes = fs::file_size(path, ec);
  if (!ec && bytes > kMaxInputBytes)
    throwInput(path, "", "", "is " + std::to_string(bytes >> 20) + " MiB, more than the " +
                                 std::to_string(kMaxInputBytes >> 20) + " MiB an input may take",
               "an input holds parameters, not data: give meshes in 'Mesh/File'");
  if (!fs::is_regular_file(path, ec)) throwInput(path, "", "", "is not a regular file");
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throwInput(path, "", "", "cannot be read (permissions?)");
  std::string content(kMaxInputBytes + 1, '\0');  // a file that grows while read stops here
  probe.read(content.data(), static_cast<std::streamsize>(content.size()));
  content.resize(static_cast<std::size_t>(probe.gcount()));
  if (content.compare(0, 3, "\xEF\xBB\xBF") == 0) content.erase(0, 3);  // a UTF-8 byte order mark
  if (content.size() > kMaxInputBytes)
    throwInput(path, "", "", "is more than the " + std::to_string(kMaxInputBytes >> 20) + " MiB an input may take");
  checkInputShape(content, path);
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
