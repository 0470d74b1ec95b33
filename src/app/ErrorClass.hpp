// How a failure is reported: the kind on stderr ("input error", "numerical failure", ...) and
// the exit code, for every error class choc throws (src/core/Errors.hpp). One table, used by the
// command line's last word and by the run summaries (<analysis>.summary.json).
#pragma once
#include <exception>
#include <string>

namespace choc {

struct ErrorClass {
  int exitCode = 4;
  std::string kind;     // "input error", "interrupted", "output failure", "out of memory",
                        // "numerical failure", "internal error"
  std::string message;  // one line
};

ErrorClass classifyError(const std::exception& e);

}  // namespace choc
