#pragma once
// What a benchmark figure depends on besides the code: the CPU model, the vector width the
// build uses, the transparent-huge-page mode and the page size. Printed in every bench
// header, so that each figure can be attributed to its host.
#include <string>

namespace rbcal::bench {

struct HostDescription {
  std::string cpu_model;    // /proc/cpuinfo "model name" ("unknown" where absent)
  int vector_doubles = 0;   // doubles per SIMD vector in this build (solver/simd.hpp)
  std::string huge_pages;   // /sys/kernel/mm/transparent_hugepage/enabled, the selected mode
  long page_bytes = 0;      // sysconf(_SC_PAGESIZE)
  std::string line() const;  // "Intel(R) Xeon(R) ..., 8 doubles per vector, THP madvise, 4 KiB pages"
};

HostDescription describe_host();

}  // namespace rbcal::bench
