// The directory a run writes into, and the only way to name a file in it.
//
// One writer per directory: the run holds an advisory lock (flock on "<dir>/.choc.lock",
// which also holds the holder's pid) for its whole life; a second run into the same directory
// is refused at once, before it touches anything. Rank 0 takes the lock; every rank learns
// the outcome.
//
// Every file a run writes or removes is `dir/<name>` with a name that holds no '/' (checked
// here): together with the output-name rule on analysis, pair and link names, nothing is
// written or removed outside the directory.
#pragma once
#include <string>
#include <vector>

#include "core/TpetraTypes.hpp"

namespace choc {

class OutputDirectory {
 public:
  // Creates the directory when missing, checks that it is a writable directory and takes
  // its lock. Throws InputError (on every rank) naming the directory and, when another run
  // holds it, that run's pid.
  OutputDirectory(const std::string& path, const Comm& comm);
  ~OutputDirectory();  // releases the lock; removes the directory if this run created it
                       // and left nothing in it (a refused input writes nothing)
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::string& path() const { return path_; }
  // "<dir>/<name>"; std::logic_error when `name` is not a plain file name.
  std::string file(const std::string& name) const;

 private:
  void lock();
  std::string path_;
  int lockFd_ = -1;
  bool created_ = false;
};

// The files an analysis named `name` can write, as names in the output directory: its
// results under their final, ".part" and ".incomplete" names, and its checkpoint. The one
// list the writers (their suffixes), the stale-result cleanup and `choc run --help` use (the
// user guide's table is tested against that help).
namespace suffix {
constexpr const char* exodus = ".exo";
constexpr const char* history = ".history.csv";
constexpr const char* impacts = ".impacts.csv";
constexpr const char* modes = ".modes.csv";
constexpr const char* checkpoint = ".checkpoint";
constexpr const char* summary = ".summary.json";
}  // namespace suffix
struct OutputFileKind {
  std::string suffix;       // ".history.csv"
  std::string description;  // for the user guide
};
const std::vector<OutputFileKind>& analysisOutputKinds();
std::vector<std::string> analysisOutputFiles(const std::string& name);
// The three names of one result: "x.history.csv" -> itself, "x.history.csv.part",
// "x.history.incomplete.csv".
std::vector<std::string> resultFileNames(const std::string& file);

}  // namespace choc
