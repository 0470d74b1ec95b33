// The "choc mesh" command: writes the two-bar impact mesh (BarImpactMesh.hpp) to Exodus.
#pragma once
#include <string>
#include <vector>

namespace choc {

// args: the command-line arguments after "mesh", e.g. {"--dim", "3", "-o", "bars.exo"}.
// Options: --dim 1|3 --length1 L --length2 L --width W --height H --along1 N --along2 N
// --across1 N --across2 N --gap G --shift-a S --axis x|y|z -o|--output FILE, --help
// ("--option=value" is also accepted). Prints a one-line summary and returns 0; a bad
// option or value throws choc::InputError (file "choc mesh", parameter = the option).
// Only MPI rank 0 writes and prints; works whether or not MPI is initialised.
int runMeshCommand(const std::vector<std::string>& args);

// The usage text printed by "choc mesh --help".
std::string meshCommandUsage();

}  // namespace choc
