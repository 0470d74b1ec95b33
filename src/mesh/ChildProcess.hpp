// Running a risky read in a child process. Debian's HDF5 1.10 frees uninitialised pointers
// on some corrupt netCDF-4 files, and may corrupt memory without crashing on others (found by
// fuzzing, confirmed with valgrind): such a file must give an input error and must not touch
// choc's own memory. The child does the whole read and sends back its result as bytes; the
// parent never runs the library on the file.
#pragma once
#include <functional>
#include <string>

namespace choc {

// Forks; the child runs `work` and sends back the bytes it returns, which this function
// returns. Throws choc::InputError with the child's own message when `work` threw one there,
// and an InputError naming `path` and `library` when the child died (a signal, a sanitizer
// abort or any other exit) or took longer than `timeoutSeconds` (it is then killed). If the
// pipe or fork cannot be made, `work` runs in this process. The child makes no MPI call and
// leaves with _exit (no atexit handler, no buffered output flushed twice).
std::string runInChildProcess(const std::string& path, const std::string& library,
                              const std::function<std::string()>& work, int timeoutSeconds = 120);

}  // namespace choc
