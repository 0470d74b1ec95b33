// Running a risky read in a child process first. Debian's HDF5 1.10 frees uninitialised
// pointers on some corrupt netCDF-4 files (found by fuzzing, confirmed with valgrind): such a
// file must give an input error, not kill choc. The child does the whole read; only if it
// succeeds does the caller read the file itself.
#pragma once
#include <functional>
#include <string>

namespace choc {

// Forks; the child runs `read` and exits. Returns when the child succeeded. Throws
// choc::InputError with the child's own message when `read` threw one there, and an
// InputError naming `path` and `library` when the child died (a signal, a sanitizer abort or
// any other exit) or took longer than `timeoutSeconds` (it is then killed). If fork itself
// fails, `read` is not probed and the function returns. The child makes no MPI call and
// leaves with _exit (no atexit handler, no buffered output flushed twice).
void probeInChildProcess(const std::string& path, const std::string& library,
                         const std::function<void()>& read, int timeoutSeconds = 120);

}  // namespace choc
