#pragma once
// How much memory this host can still give: for refusals made before a large allocation.
#include <cstdint>

namespace rbcal::formats {

// MemAvailable of /proc/meminfo (the memory the kernel can give without swapping), or 0 when
// unknown.
std::uint64_t available_memory_bytes();

}  // namespace rbcal::formats
