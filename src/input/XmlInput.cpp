#include "input/XmlInput.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <Teuchos_XMLParameterListHelpers.hpp>

#include "input/Errors.hpp"

namespace choc {

namespace {
std::string firstLine(const std::string& s) {
  std::string line;
  std::istringstream in(s);
  while (std::getline(in, line)) {
    // Teuchos messages start with a file:line banner; keep the first informative line.
    if (line.find_first_not_of(" \t") == std::string::npos) continue;
    if (line.find("Throw number") != std::string::npos) continue;
    if (line.find("Throw test") != std::string::npos) continue;
    if (line.rfind("/", 0) == 0 && line.find(":") != std::string::npos &&
        line.find("Error") == std::string::npos)
      continue;
    return line;
  }
  return s;
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
  try {
    return Teuchos::getParametersFromXmlString(content);
  } catch (const std::exception& e) {
    throwInput(path, "", "", "malformed XML parameter list: " + firstLine(e.what()),
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
