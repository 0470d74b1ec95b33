// File-system operations that never throw anything but choc's own errors: each failure is
// one OutputError naming the file and the system's reason (errno text). A caller before the
// run starts turns it into an input error (exit 1); during the run it is an output failure
// (exit 2). No other code in src/ calls a std::filesystem function that can throw.
#pragma once
#include <string>
#include <vector>

namespace choc {

// The system's text for an errno value ("No space left on device").
std::string systemError(int err);

// Removes a file; a missing one is not an error.
void removeFile(const std::string& path);
// Renames `from` to `to` (replacing `to`).
void renameFile(const std::string& from, const std::string& to);
bool fileExists(const std::string& path);      // anything at the path (never throws)
bool isDirectory(const std::string& path);     // a directory at the path (never throws)
bool isRegularFile(const std::string& path);   // a plain file at the path (never throws)
// Writes `text` to "<path>.part" and renames it to `path` (complete) or `incomplete`. When the
// write fails (OutputError), nothing is left; with `keepWholeLines` (a table of rows), the whole
// lines that reached the disk are kept as `incomplete` (a row never half-written).
void writeWholeFile(const std::string& path, const std::string& text, bool complete,
                    const std::string& incomplete, bool keepWholeLines = false);
// The names in a directory (not "." and ".."), with their modification times; empty when it
// cannot be read.
struct DirectoryEntry {
  std::string name;
  double modified = 0;  // seconds since the epoch
};
std::vector<DirectoryEntry> listDirectory(const std::string& path);
// True when both paths name the same existing file (device and inode).
bool sameFile(const std::string& a, const std::string& b);
// Writes all of `data` to the descriptor (restarting after EINTR). Returns 0, or the errno of
// the failed write (ENOSPC when the disk accepted only part of it).
int writeFully(int fd, const char* data, std::size_t size, std::size_t* written = nullptr);

}  // namespace choc
