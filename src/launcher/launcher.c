/* build/choc: starts build/choc-engine with SIGINT and SIGTERM blocked.
 *
 * Loading choc's shared libraries (Trilinos, MPI, HDF5) takes a few tenths of a second before
 * any of its code runs; a signal then would stop the process by its default action, without a
 * word. This launcher loads only the C library, blocks the two signals and replaces itself by
 * the engine (same process, same pid): a signal received meanwhile stays pending across the
 * exec, and the engine delivers it to its own handler once installed, so it is a clean stop like
 * any other (src/output/Interrupt.hpp). */
#include <errno.h>
#include <limits.h>
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

int main(int argc, char** argv) {
  (void)argc;
  sigset_t both;
  sigemptyset(&both);
  sigaddset(&both, SIGINT);
  sigaddset(&both, SIGTERM);
  sigprocmask(SIG_BLOCK, &both, NULL);
  char path[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", path, sizeof path - 32);
  if (n <= 0) {
    fprintf(stderr, "choc: internal error: cannot find the choc executable (%s)\n", strerror(errno));
    return 4;
  }
  path[n] = '\0';
  char* slash = strrchr(path, '/');
  strcpy(slash ? slash + 1 : path, "choc-engine");
  execv(path, argv);
  fprintf(stderr, "choc: internal error: cannot start %s (%s)\n", path, strerror(errno));
  return 4;
}
