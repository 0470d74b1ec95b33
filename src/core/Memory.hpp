// Out-of-memory reporting. choc replaces the global operator new so that a failed allocation
// records its size before std::bad_alloc is thrown; outOfMemoryMessage() turns any allocation
// failure (std::bad_alloc, Kokkos' allocation failure) into one line saying how much was asked
// and how much the process held.
#pragma once
#include <cstddef>
#include <exception>
#include <string>

namespace choc {

// The size of the last allocation operator new could not serve (0 if none).
std::size_t lastFailedAllocation();
// "" when `e` is not an allocation failure; else the message of the OutOfMemory error.
std::string outOfMemoryMessage(const std::exception& e);
// What a caught exception says, for a message shared across ranks: "out of memory: ..." for an
// allocation failure, else its first line.
std::string describeFailure(const std::exception& e);
// Throws OutOfMemory("<context>: ...") when `failure` (from describeFailure) is an allocation
// failure; returns otherwise.
void rethrowIfOutOfMemory(const std::string& failure, const std::string& context);
// "3.2 GiB"
std::string byteSize(double bytes);
// True when `bytes` more can be allocated now (a probe: malloc, then free).
bool canAllocate(std::size_t bytes);

}  // namespace choc
