#include "core/Memory.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <string>

#include <Kokkos_Core.hpp>

#include "core/Errors.hpp"
#include "core/Resources.hpp"

namespace {
std::size_t g_failedSize = 0;
}

// Sanitizer builds keep their own allocator's operators (they check new/delete pairs).
#if !defined(__SANITIZE_ADDRESS__)
void* operator new(std::size_t n) {
  if (n == 0) n = 1;
  for (;;) {
    if (void* p = std::malloc(n)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) {
      g_failedSize = n;
      throw std::bad_alloc();
    }
    handler();
  }
}
void* operator new[](std::size_t n) { return ::operator new(n); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
#endif

namespace choc {

std::size_t lastFailedAllocation() { return g_failedSize; }

std::string byteSize(double bytes) {
  const char* unit[] = {"bytes", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024.0 && u < 4) {
    bytes /= 1024.0;
    ++u;
  }
  char buf[48];
  std::snprintf(buf, sizeof buf, u == 0 ? "%.0f %s" : "%.1f %s", bytes, unit[u]);
  return buf;
}

bool canAllocate(std::size_t bytes) {
  void* p = std::malloc(bytes);
  std::free(p);
  return p != nullptr;
}

namespace {

std::string held() { return "; the process held " + byteSize(peakResidentBytes()) + " at its peak"; }

// Kokkos reports a failed allocation as a runtime_error: "Kokkos failed to allocate memory for
// label ... Allocation of size 77.59 M failed ..." (a human-readable size: B, K, M, G).
std::size_t kokkosSize(const std::string& what) {
  const std::size_t at = what.find("Allocation of size ");
  if (at == std::string::npos) return 0;
  char* end = nullptr;
  double n = std::strtod(what.c_str() + at + 19, &end);
  while (end && *end == ' ') ++end;
  const std::string units = "KMGT";
  const std::size_t u = end ? units.find(*end) : std::string::npos;
  if (u != std::string::npos) n *= std::pow(1024.0, double(u + 1));
  return static_cast<std::size_t>(n);
}

}  // namespace

std::string outOfMemoryMessage(const std::exception& e) {
  const std::string fix = "; run on more ranks or a machine with more memory, or reduce the model";
  if (const auto* k = dynamic_cast<const Kokkos::Experimental::RawMemoryAllocationFailure*>(&e))
    return "an allocation of " + byteSize(double(k->attempted_size())) + " failed" + held() + fix;
  if (dynamic_cast<const std::bad_alloc*>(&e)) {
    const std::size_t n = lastFailedAllocation();
    return (n > 0 ? "an allocation of " + byteSize(double(n)) + " failed" : std::string("an allocation failed")) +
           held() + fix;
  }
  const std::string what = e.what();
  if (what.find("failed to allocate") != std::string::npos || what.find("insufficient memory") != std::string::npos) {
    const std::size_t n = kokkosSize(what);
    return (n > 0 ? "an allocation of " + byteSize(double(n)) + " failed" : std::string("an allocation failed")) +
           " (Kokkos)" + held() + fix;
  }
  return "";
}

namespace {
const char kOutOfMemory[] = "out of memory: ";
}

std::string describeFailure(const std::exception& e) {
  const std::string oom = outOfMemoryMessage(e);
  if (!oom.empty()) return kOutOfMemory + oom;
  std::string what = e.what();
  return what.substr(0, what.find('\n'));
}

void rethrowIfOutOfMemory(const std::string& failure, const std::string& context) {
  const std::string marker = kOutOfMemory;
  if (failure.compare(0, marker.size(), marker) == 0)
    throw OutOfMemory(context + ": " + failure.substr(marker.size()));
}

}  // namespace choc
