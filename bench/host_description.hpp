#pragma once
// What a benchmark figure depends on besides the code: the CPU model and its signature, the
// vector width the build uses, the transparent-huge-page mode and the page size. Printed in
// every bench header, so that each figure can be attributed to its host. Under a hypervisor
// the model name can be generic ("Intel(R) Xeon(R) Processor"); the vendor, family and model
// numbers still tell the microarchitecture.
#include <istream>
#include <string>

namespace rbcal::bench {

struct HostDescription {
  std::string cpu_model;      // /proc/cpuinfo "model name" ("unknown" where absent)
  std::string cpu_signature;  // "GenuineIntel family 6 model 143" ("unknown" where absent)
  int vector_doubles = 0;     // doubles per SIMD vector in this build (solver/simd.hpp)
  std::string huge_pages;     // /sys/kernel/mm/transparent_hugepage/enabled, the selected mode
  long page_bytes = 0;        // sysconf(_SC_PAGESIZE)
  // "Intel(R) Xeon(R) ... (GenuineIntel family 6 model 143), 8 doubles per vector, THP madvise, 4 KiB pages"
  std::string line() const;
};

HostDescription describe_host();

// The first processor's "model name", and its vendor, family and model ("GenuineIntel family
// 6 model 143"), from /proc/cpuinfo text ("unknown" where absent).
struct CpuIdentity {
  std::string model, signature;
};
CpuIdentity cpu_identity_of(std::istream& cpuinfo);

// This process's anonymous memory and the part of it in transparent huge pages, from
// /proc/self/smaps_rollup text (zeros where the fields are absent). Whether the large arrays
// got the huge pages they ask for (madvise) decides the fluid update's TLB misses.
struct MemoryUse {
  double anonymous_bytes = 0.0, huge_page_bytes = 0.0;
};
MemoryUse memory_use_of(std::istream& smaps_rollup);
MemoryUse memory_use();  // of this process now

}  // namespace rbcal::bench
