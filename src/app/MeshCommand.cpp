// "choc mesh": option parsing, generation, writing on rank 0, one-line summary.
#include "app/MeshCommand.hpp"

#include <mpi.h>

#include <cctype>
#include <exception>
#include <iostream>
#include <limits>
#include <sstream>

#include "core/Errors.hpp"
#include "mesh/BarImpactMesh.hpp"
#include "mesh/ExodusMeshWriter.hpp"
#include "mesh/MeshFile.hpp"

namespace choc {

namespace {

const char* const kCommand = "choc mesh";

double parseDouble(const std::string& option, const std::string& value) {
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size())
    throwInput(kCommand, option, value, "is not a number", "give a number, e.g. 0.02 or 1e-5");
  return v;
}

int parseInt(const std::string& option, const std::string& value) {
  std::size_t used = 0;
  long long v = 0;
  try {
    v = std::stoll(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (value.empty() || used != value.size() || v < std::numeric_limits<int>::min() ||
      v > std::numeric_limits<int>::max())
    throwInput(kCommand, option, value, "is not an integer", "give a whole number, e.g. 50");
  return static_cast<int>(v);
}

char parseAxis(const std::string& value) {
  if (value.size() == 1) {
    const char c = static_cast<char>(std::tolower(static_cast<unsigned char>(value[0])));
    if (c == 'x' || c == 'y' || c == 'z') return c;
  }
  throwInput(kCommand, "--axis", value, "must be x, y or z", "give the axis of the bars");
}

bool isKnown(const std::string& option) {
  for (const char* known : {"--dim", "--length1", "--length2", "--width", "--height", "--along1",
                            "--along2", "--across1", "--across2", "--gap", "--shift-a",
                            "--axis", "-o", "--output"})
    if (option == known) return true;
  return false;
}

// Applies one known option.
void apply(const std::string& option, const std::string& value, BarImpactOptions& o,
           std::string& output) {
  if (option == "--dim") o.dimension = parseInt(option, value);
  else if (option == "--length1") o.length1 = parseDouble(option, value);
  else if (option == "--length2") o.length2 = parseDouble(option, value);
  else if (option == "--width") o.width = parseDouble(option, value);
  else if (option == "--height") o.height = parseDouble(option, value);
  else if (option == "--along1") o.along1 = parseInt(option, value);
  else if (option == "--along2") o.along2 = parseInt(option, value);
  else if (option == "--across1") o.across1 = parseInt(option, value);
  else if (option == "--across2") o.across2 = parseInt(option, value);
  else if (option == "--gap") o.gap = parseDouble(option, value);
  else if (option == "--shift-a") o.shiftA = parseDouble(option, value);
  else if (option == "--axis") o.axis = parseAxis(value);
  else if (option == "-o" || option == "--output") {
    if (value.empty())
      throwInput(kCommand, option, value, "is empty", "give the output file, e.g. -o bars.exo");
    output = value;
  }
}

std::string join(const std::vector<std::string>& names) {
  if (names.empty()) return "none";
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ", ") + n;
  return s;
}

std::string summary(const std::string& file, const Mesh& mesh) {
  std::ostringstream s;
  s << "wrote " << file << ": " << mesh.numNodes() << " nodes, " << mesh.numElements()
    << " elements, blocks ";
  for (std::size_t b = 0; b < mesh.blocks.size(); ++b)
    s << (b ? ", " : "") << mesh.blocks[b].name << " (" << mesh.blocks[b].topology << " x"
      << mesh.blocks[b].numElements() << ")";
  s << ", node sets " << join(mesh.nodeSetNames()) << ", side sets " << join(mesh.sideSetNames());
  return s.str();
}

int mpiRank() {
  int initialized = 0, finalized = 0, rank = 0;
  MPI_Initialized(&initialized);
  MPI_Finalized(&finalized);
  if (initialized && !finalized) MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  return rank;
}

}  // namespace

std::string meshCommandUsage() {
  const BarImpactOptions d;
  std::ostringstream s;
  s << "usage: choc mesh [options] -o FILE.exo\n"
       "       choc mesh import MESH.msh -o FILE.exo   (any mesh choc reads, as Exodus II)\n"
       "Writes the two-bar impact mesh: bar 1 (POU1, A..B) from s = gap to gap + length1,\n"
       "bar 2 (POU2, C..D) from s = 0 to -length2, s along the axis.\n"
       "  --dim 1|3        1: BEAM2 line elements, 3: HEX8 bricks (default "
    << d.dimension << ")\n"
    << "  --length1 L      length of bar 1 (default " << d.length1 << ")\n"
    << "  --length2 L      length of bar 2 (default " << d.length2 << ")\n"
    << "  --width W        section side along the first lateral axis, 3D (default " << d.width
    << ")\n"
    << "  --height H       section side along the second lateral axis, 3D (default " << d.height
    << ")\n"
    << "  --along1 N       elements along bar 1 (default " << d.along1 << ")\n"
    << "  --along2 N       elements along bar 2 (default " << d.along2 << ")\n"
    << "  --across1 N      elements across bar 1 per lateral direction, 3D (default "
    << d.across1 << ")\n"
    << "  --across2 N      elements across bar 2 per lateral direction, 3D (default "
    << d.across2 << ")\n"
    << "  --gap G          distance from C to A, may be 0 or negative (default " << d.gap << ")\n"
    << "  --shift-a S      moves node A alone along the axis, 1D only (default " << d.shiftA
    << ")\n"
    << "  --axis x|y|z     axis of the bars (default " << d.axis << ")\n"
    << "  -o, --output F   the Exodus II file to write (required)\n"
    << "  --help           this text\n";
  return s.str();
}

namespace {

// Writes `mesh` to `output` on rank 0 and prints the one-line summary.
int writeMesh(const Mesh& mesh, const std::string& output) {
  if (mpiRank() != 0) return 0;
  try {
    writeExodusMesh(mesh, output);
  } catch (const std::exception& e) {
    throwInput(kCommand, "-o", output, std::string("cannot write the file (") + e.what() + ")",
               "check that the directory exists and is writable");
  }
  std::cout << summary(output, mesh) << std::endl;
  return 0;
}

// choc mesh import MESH -o FILE.exo: any mesh choc reads, written as Exodus II.
int runMeshImport(const std::vector<std::string>& args) {
  const std::string cmd = "choc mesh import";
  std::string input, output;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "-o" || args[i] == "--output") {
      if (i + 1 >= args.size()) throwInput(cmd, args[i], "", "needs a value", "add -o FILE.exo");
      output = args[++i];
    } else if (!args[i].empty() && args[i][0] == '-') {
      throwInput(cmd, args[i], "", "unknown option", "usage: choc mesh import MESH.msh -o FILE.exo");
    } else if (input.empty()) {
      input = args[i];
    } else {
      throwInput(cmd, "", args[i], "one mesh file expected, got '" + input + "' and '" + args[i] + "'");
    }
  }
  if (input.empty()) throwInput(cmd, "", "", "no mesh file given", "usage: choc mesh import MESH.msh -o FILE.exo");
  if (output.empty()) throwInput(cmd, "-o", "", "no output file given", "add -o FILE.exo");
  return writeMesh(readMeshFile(input), output);
}

}  // namespace

int runMeshCommand(const std::vector<std::string>& args) {
  if (!args.empty() && args[0] == "import")
    return runMeshImport(std::vector<std::string>(args.begin() + 1, args.end()));
  BarImpactOptions options;
  std::string output;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (arg == "--help" || arg == "-h") {
      if (mpiRank() == 0) std::cout << meshCommandUsage();
      return 0;
    }
    if (arg.size() < 2 || arg[0] != '-')
      throwInput(kCommand, "", arg, "unexpected argument '" + arg + "'",
                 "options start with '-'; run 'choc mesh --help'");
    std::string option = arg, value;
    const std::size_t eq = arg.rfind("--", 0) == 0 ? arg.find('=') : std::string::npos;
    if (eq != std::string::npos) {
      option = arg.substr(0, eq);
      value = arg.substr(eq + 1);
    }
    if (!isKnown(option))
      throwInput(kCommand, option, "", "unknown option", "run 'choc mesh --help' for the list");
    if (eq == std::string::npos) {
      if (i + 1 >= args.size())
        throwInput(kCommand, option, "", "needs a value", "run 'choc mesh --help'");
      value = args[++i];
    }
    apply(option, value, options, output);
  }
  validateBarImpactOptions(options);  // option errors first, then the missing output
  if (output.empty())
    throwInput(kCommand, "-o", "", "no output file given", "add -o FILE.exo");
  return writeMesh(generateBarImpactMesh(options), output);
}

}  // namespace choc
