// Both fuzz targets read from a path: each input is written to one file per fuzzing process.
#pragma once
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

// Writes the input to $TMPDIR (or /tmp)/choc_fuzz_<stem>_<pid>.<ext> and returns that path;
// aborts (a finding) if the file cannot be written.
inline const std::string& writeFuzzInput(const uint8_t* data, size_t size, const char* stem,
                                         const char* ext) {
  static const std::string path = [&] {
    const char* dir = std::getenv("TMPDIR");
    return std::string(dir && *dir ? dir : "/tmp") + "/choc_fuzz_" + stem + "_" +
           std::to_string(getpid()) + "." + ext;
  }();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) std::abort();
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  return path;
}
