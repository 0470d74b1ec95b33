#include "restart/CheckpointFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>

#include "core/Errors.hpp"
#include "core/Files.hpp"

namespace choc {

namespace {

const char kMagic[] = "CHOC-CHECKPOINT 1\n";
constexpr std::size_t kMagicLength = sizeof(kMagic) - 1;

void putU64(std::vector<char>& out, std::uint64_t n) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((n >> (8 * i)) & 0xff));
}

std::uint64_t getU64(const std::vector<char>& in, std::size_t pos) {
  std::uint64_t n = 0;
  for (int i = 0; i < 8; ++i) n |= std::uint64_t(static_cast<unsigned char>(in[pos + i])) << (8 * i);
  return n;
}

[[noreturn]] void writeFailure(const std::string& path, const std::string& what, int err) {
  throw OutputError("checkpoint " + path + ": " + what + " failed (" + std::strerror(err) +
                    "; disk full or file-size limit?); the previous checkpoint, if any, is kept");
}

// Writes all of `data` to fd.
void writeAll(int fd, const std::vector<char>& data, const std::string& path) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int err = n < 0 ? errno : EIO;
      ::close(fd);
      ::unlink((path + ".tmp").c_str());
      writeFailure(path, "writing", err);
    }
    done += static_cast<std::size_t>(n);
  }
}

}  // namespace

void writeCheckpointFile(const std::string& path, const StateArchive& archive) {
  const std::vector<char> payload = archive.serialize();
  std::vector<char> data(kMagic, kMagic + kMagicLength);
  putU64(data, payload.size());
  data.insert(data.end(), payload.begin(), payload.end());
  putU64(data, fnv1a(payload.data(), payload.size()));
  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) writeFailure(path, "creating " + tmp, errno);
  writeAll(fd, data, path);
  if (::fsync(fd) != 0) {
    const int err = errno;
    ::close(fd);
    ::unlink(tmp.c_str());
    writeFailure(path, "fsync", err);
  }
  if (::close(fd) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    writeFailure(path, "closing", err);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int err = errno;
    ::unlink(tmp.c_str());
    writeFailure(path, "renaming " + tmp, err);
  }
  // The rename itself survives a crash once the directory is on disk.
  const std::size_t slash = path.rfind('/');
  const std::string dir = slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

StateArchive readCheckpointFile(const std::string& path) {
  if (fileExists(path) && !isRegularFile(path))
    throw InputError(path + ": option '--restart': is not a file; name the <analysis>.checkpoint "
                            "file a stopped run wrote");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": option '--restart': the checkpoint cannot be opened (" +
                     std::strerror(errno) + ")");
  std::vector<char> data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto refuse = [&](const std::string& why) {
    throw InputError(path + ": option '--restart': " + why +
                     "; restart from another checkpoint or run from the start");
  };
  if (data.size() < kMagicLength || std::memcmp(data.data(), kMagic, kMagicLength) != 0)
    refuse("not a choc checkpoint (no 'CHOC-CHECKPOINT 1' header)");
  if (data.size() < kMagicLength + 16) refuse("truncated checkpoint (" + std::to_string(data.size()) + " bytes)");
  const std::uint64_t n = getU64(data, kMagicLength);
  if (n != data.size() - kMagicLength - 16)
    refuse("truncated or corrupt checkpoint (" + std::to_string(data.size()) + " bytes for a payload of " +
           std::to_string(n) + ")");
  const std::vector<char> payload(data.begin() + kMagicLength + 8, data.end() - 8);
  if (fnv1a(payload.data(), payload.size()) != getU64(data, data.size() - 8))
    refuse("corrupt checkpoint (checksum mismatch)");
  try {
    return StateArchive::parse(payload);
  } catch (const StateRecordError& e) {
    refuse(std::string("corrupt checkpoint (") + e.what() + ")");
  }
}

}  // namespace choc
