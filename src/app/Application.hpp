// The choc command line: run, check, parameters, mesh.
#pragma once

namespace choc {

// Exit codes: 0 success, 1 input error, 2 numerical failure, 3 a check failed,
// 4 internal error (a bug: please report it).
int runApplication(int argc, char** argv);

}  // namespace choc
