#include "app/ErrorClass.hpp"

#include "core/Errors.hpp"
#include "core/Memory.hpp"
#include "output/Interrupt.hpp"

namespace choc {

ErrorClass classifyError(const std::exception& e) {
  if (dynamic_cast<const InputError*>(&e)) return {kExitInputError, "input error", e.what()};
  if (const auto* i = dynamic_cast<const Interrupted*>(&e)) return {i->exitCode(), "interrupted", e.what()};
  if (dynamic_cast<const OutputError*>(&e)) return {kExitNumericalFailure, "output failure", e.what()};
  if (dynamic_cast<const OutOfMemory*>(&e)) return {kExitNumericalFailure, "out of memory", e.what()};
  if (dynamic_cast<const NumericalError*>(&e)) return {kExitNumericalFailure, "numerical failure", e.what()};
  const std::string oom = outOfMemoryMessage(e);
  if (!oom.empty()) return {kExitNumericalFailure, "out of memory", oom};
  const std::string m = e.what();
  return {kExitInternalError, "internal error", m.substr(0, m.find('\n'))};
}

}  // namespace choc
