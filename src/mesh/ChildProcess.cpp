#include "mesh/ChildProcess.hpp"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <string>

#include "core/Errors.hpp"

namespace choc {

namespace {

constexpr int kReadOk = 0, kInputError = 97, kOtherException = 98;

bool writeAll(int fd, const std::string& text) {
  const char* p = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return true;
}

[[noreturn]] void childMain(int fd, const std::function<std::string()>& work) {
  // A crash of the child is the expected failure: it dies quietly (no crash report from the
  // handlers Open MPI installs), the parent gives the one-line error.
  for (int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) ::signal(sig, SIG_DFL);
  int code = kReadOk;
  try {
    if (!writeAll(fd, work())) code = kOtherException;  // a result cut short is no result
  } catch (const InputError& e) {
    writeAll(fd, e.what());
    code = kInputError;
  } catch (...) {
    code = kOtherException;
  }
  ::close(fd);
  ::_exit(code);
}

}  // namespace

std::string runInChildProcess(const std::string& path, const std::string& library,
                              const std::function<std::string()>& work, int timeoutSeconds) {
  int fds[2];
  if (::pipe(fds) != 0) return work();
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return work();
  }
  if (pid == 0) {
    ::close(fds[0]);
    childMain(fds[1], work);
  }
  ::close(fds[1]);
  std::string output;  // the result, or the message of an InputError
  bool timedOut = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutSeconds);
  for (;;) {  // until the child closes its end (it exits) or the deadline
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timedOut = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) {  // cannot wait for the child: stop it
      timedOut = true;
      break;
    }
    if (ready <= 0) continue;
    char buffer[65536];
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (timedOut) ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!timedOut && WIFEXITED(status) && WEXITSTATUS(status) == kReadOk) return output;
  if (!timedOut && WIFEXITED(status) && WEXITSTATUS(status) == kInputError)
    throw InputError(output);
  const std::string how =
      timedOut ? "took more than " + std::to_string(timeoutSeconds) + " s"
      : WIFSIGNALED(status) ? std::string("crashed (signal ") + std::to_string(WTERMSIG(status)) +
                                  ", " + ::strsignal(WTERMSIG(status)) + ")"
                            : "failed (exit code " + std::to_string(WEXITSTATUS(status)) + ")";
  throwInput(path, "", "", "the " + library + " library " + how + " reading this file: it is corrupt",
             library == "gmsh" ? "check that the file is a complete gmsh mesh (.msh, format 4 or 2.2)"
                               : "check that the file is a complete Exodus II mesh");
}

}  // namespace choc
