#include "core/Files.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "core/Errors.hpp"

namespace choc {

std::string systemError(int err) { return std::strerror(err); }

void removeFile(const std::string& path) {
  if (::unlink(path.c_str()) != 0 && errno != ENOENT)
    throw OutputError("cannot remove " + path + ": " + systemError(errno));
}

void renameFile(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0)
    throw OutputError("cannot rename " + from + " to " + to + ": " + systemError(errno));
}

bool fileExists(const std::string& path) {
  struct stat st {};
  return ::lstat(path.c_str(), &st) == 0;
}

bool isDirectory(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

bool isRegularFile(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

std::vector<DirectoryEntry> listDirectory(const std::string& path) {
  std::vector<DirectoryEntry> out;
  DIR* d = ::opendir(path.c_str());
  if (!d) return out;
  while (const dirent* e = ::readdir(d)) {
    const std::string name = e->d_name;
    if (name == "." || name == "..") continue;
    struct stat st {};
    DirectoryEntry entry{name, 0.0};
    if (::lstat((path + "/" + name).c_str(), &st) == 0)
      entry.modified = double(st.st_mtim.tv_sec) + 1e-9 * double(st.st_mtim.tv_nsec);
    out.push_back(entry);
  }
  ::closedir(d);
  return out;
}

bool sameFile(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  return ::stat(a.c_str(), &sa) == 0 && ::stat(b.c_str(), &sb) == 0 && sa.st_dev == sb.st_dev &&
         sa.st_ino == sb.st_ino;
}

int writeFully(int fd, const char* data, std::size_t size, std::size_t* written) {
  std::size_t local = 0;
  std::size_t& done = written ? *written : local;
  done = 0;
  while (done < size) {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return errno;
    if (n == 0) return ENOSPC;
    done += static_cast<std::size_t>(n);
  }
  return 0;
}

void writeWholeFile(const std::string& path, const std::string& text, bool complete,
                    const std::string& incomplete, bool keepWholeLines) {
  const std::string part = path + ".part";
  const int fd = ::open(part.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw OutputError("cannot create " + part + ": " + systemError(errno));
  std::size_t written = 0;
  int err = writeFully(fd, text.data(), text.size(), &written);
  const std::size_t lines = keepWholeLines ? text.rfind('\n', written == 0 ? 0 : written - 1) : std::string::npos;
  const bool keep = err != 0 && written > 0 && lines != std::string::npos && ::ftruncate(fd, off_t(lines + 1)) == 0;
  if (::close(fd) != 0 && err == 0) err = errno;
  if (err != 0) {
    if (keep)
      ::rename(part.c_str(), incomplete.c_str());  // the whole rows that reached the disk
    else
      ::unlink(part.c_str());  // nothing of it is worth keeping: it is written at once
    throw OutputError("writing " + part + " failed: " + systemError(err) + " (disk full or file-size limit?)" +
                      (keep ? "; its whole rows are in " + incomplete : ""));
  }
  renameFile(part, complete ? path : incomplete);
}

}  // namespace choc
