#include "output/OutputDirectory.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/Errors.hpp"
#include "core/Files.hpp"
#include "core/CollectiveFailure.hpp"

namespace choc {

namespace {

const char kLockName[] = ".choc.lock";

bool isRoot(const Comm& comm) { return comm.getRank() == 0; }

// mkdir -p, one level at a time; true when this call created the last level.
bool makeDirectories(const std::string& path) {
  std::string prefix;
  bool created = false;
  std::size_t pos = 0;
  while (pos != std::string::npos) {
    pos = path.find('/', pos + 1);
    prefix = path.substr(0, pos);
    if (prefix.empty()) continue;
    if (::mkdir(prefix.c_str(), 0755) == 0) {
      created = true;
      continue;
    }
    if (errno != EEXIST)
      throw InputError("choc run: output directory '" + path + "': cannot create " + prefix +
                       ": " + systemError(errno) + "; give a writable directory with -o DIR");
    created = false;
  }
  return created;
}

// The holder writes its pid just after taking the lock: a run refused in between waits for it
// (up to 0.2 s).
std::string readHolder(int fd) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    char buf[64] = {};
    const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    std::string s = n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : std::string();
    if (!s.empty() && s.back() == '\n') {
      s.pop_back();
      return s;
    }
    ::usleep(10000);
  }
  return "unknown";
}

}  // namespace

OutputDirectory::OutputDirectory(const std::string& path, const Comm& comm)
    : path_(path) {
  while (path_.size() > 1 && path_.back() == '/') path_.pop_back();
  std::string failure;
  if (isRoot(comm)) {
    try {
      created_ = makeDirectories(path_);
      if (!isDirectory(path_))
        throw InputError("choc run: output directory '" + path_ +
                         "' is not a directory; give a directory with -o DIR");
      if (::access(path_.c_str(), W_OK | X_OK) != 0)
        throw InputError("choc run: output directory '" + path_ + "' is not writable (" +
                         systemError(errno) + "); give a writable directory with -o DIR");
      lock();
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  failure = collectiveFailure(comm, failure);
  if (!failure.empty()) {
    if (lockFd_ >= 0) ::close(lockFd_);
    lockFd_ = -1;
    throw InputError(failure);
  }
}

// flock on "<dir>/.choc.lock". The file is removed when the run ends, so a run that opened it
// just before may hold a lock on a removed file: after locking, the path must still name the
// locked file, or the lock is taken again on the new one.
void OutputDirectory::lock() {
  const std::string lockPath = path_ + "/" + kLockName;
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0)
      throw InputError("choc run: output directory '" + path_ + "': cannot create its lock " +
                       lockPath + ": " + systemError(errno) + "; give a writable directory with -o DIR");
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const int err = errno;
      const std::string holder = readHolder(fd);
      ::close(fd);
      if (err == EWOULDBLOCK)
        throw InputError("choc run: output directory '" + path_ +
                         "' is in use by another choc run (pid " + holder +
                         "); wait for it to end, or give another directory with -o DIR");
      throw InputError("choc run: output directory '" + path_ + "': cannot lock " + lockPath +
                       ": " + systemError(err));
    }
    struct stat held {}, named {};
    if (::fstat(fd, &held) == 0 && ::stat(lockPath.c_str(), &named) == 0 &&
        held.st_ino == named.st_ino && held.st_dev == named.st_dev) {
      const std::string pid = std::to_string(::getpid()) + "\n";
      if (::ftruncate(fd, 0) == 0) writeFully(fd, pid.data(), pid.size());
      lockFd_ = fd;
      return;
    }
    ::close(fd);  // the file was removed by the run that held it: lock the new one
  }
  throw InputError("choc run: output directory '" + path_ + "': cannot take its lock " + lockPath);
}

OutputDirectory::~OutputDirectory() {
  if (lockFd_ < 0) return;
  ::unlink((path_ + "/" + kLockName).c_str());  // while still holding it (see lock())
  ::close(lockFd_);
  if (created_) ::rmdir(path_.c_str());  // fails, as it should, unless the run left it empty
}

std::string OutputDirectory::file(const std::string& name) const {
  if (name.empty() || name == "." || name == ".." || name.find('/') != std::string::npos ||
      name.find('\0') != std::string::npos)
    throw std::logic_error("output file name '" + name + "' is not a plain file name");
  return path_ + "/" + name;
}

const std::vector<OutputFileKind>& analysisOutputKinds() {
  static const std::vector<OutputFileKind> kinds = {
      {suffix::exodus, "Exodus II results: the mesh and the nodal fields (modes, or states of a transient)"},
      {suffix::history, "the history of a transient: one row per step"},
      {suffix::impacts, "one row per impact of each shock link or contact pair"},
      {suffix::modes, "the modes of a modal analysis: frequency, generalized mass, residual"},
      {suffix::checkpoint, "the state a stopped transient continues from (--restart)"},
      {suffix::summary, "what the analysis did, for tools: status, exit reason, steps, iterations, "
                        "energy, timers, memory, version and input hash"},
  };
  return kinds;
}

std::vector<std::string> resultFileNames(const std::string& file) {
  const std::size_t dot = file.rfind('.');
  const std::string incomplete = dot == std::string::npos || dot == 0
                                     ? file + ".incomplete"
                                     : file.substr(0, dot) + ".incomplete" + file.substr(dot);
  return {file, file + ".part", incomplete};
}

std::vector<std::string> analysisOutputFiles(const std::string& name) {
  std::vector<std::string> out;
  for (const OutputFileKind& k : analysisOutputKinds()) {
    if (k.suffix == suffix::checkpoint) {
      out.push_back(name + k.suffix);
      out.push_back(name + k.suffix + ".tmp");
      continue;
    }
    for (const std::string& f : resultFileNames(name + k.suffix)) out.push_back(f);
  }
  return out;
}

}  // namespace choc
