// Error kinds and the exit codes they map to (the README's exit-code table).
#pragma once
#include <stdexcept>
#include <string>

namespace choc {

enum ExitCode : int {
  kExitOk = 0,
  kExitInputError = 1,       // bad input: file, parameter, value
  kExitNumericalFailure = 2, // a solver, Newton or the active set failed; a result not writable
  kExitCheckFailed = 3,      // a declared check is NOOK
  kExitInternalError = 4,    // an unexpected exception (a bug): please report it
  kExitInterruptBase = 128,  // + the signal: 130 after SIGINT, 143 after SIGTERM
};

// Bad input. The message is one line naming the file, the parameter, the value and the fix.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A solver did not converge, a matrix is singular, a result is not finite (exit 2).
class NumericalError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A state outside the model's domain (an element inverted: det F <= 0), agreed on by every
// rank. An implicit step treats it as a failed attempt and cuts dt; an explicit run stops (exit
// 2), its message naming the element, the block and the time.
class InadmissibleState : public NumericalError {
 public:
  using NumericalError::NumericalError;
};

// A results or checkpoint file that cannot be written (disk full, file-size limit): exit 2,
// like a numerical failure (the run cannot produce its result), one line naming the file.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Out of memory (exit 2): an allocation of choc's, of Trilinos' (Kokkos) or of a factorisation
// failed. The message says how much was asked when it is known.
class OutOfMemory : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "<file>: parameter '<path>' = '<value>': <problem>; <fix>" (parts left out when empty).
std::string inputMessage(const std::string& file, const std::string& parameter,
                         const std::string& value, const std::string& problem,
                         const std::string& fix = "");

[[noreturn]] void throwInput(const std::string& file, const std::string& parameter,
                             const std::string& value, const std::string& problem,
                             const std::string& fix = "");

}  // namespace choc
