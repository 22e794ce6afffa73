// The bench header's host fields, parsed from /proc text as Linux writes it: the first
// processor's block of /proc/cpuinfo (an Intel Xeon guest under KVM as its kernel printed
// it, and the same fields as an AMD Zen 4 guest gives them: vendor AuthenticAMD, family 25)
// and /proc/self/smaps_rollup.
#include <gtest/gtest.h>

#include <sstream>

#include "bench/host_description.hpp"

namespace rbcal::bench {
namespace {

const char* kIntelGuest =
    "processor\t: 0\n"
    "vendor_id\t: GenuineIntel\n"
    "cpu family\t: 6\n"
    "model\t\t: 167\n"
    "model name\t: Intel(R) Xeon(R) Processor\n"
    "stepping\t: 1\n"
    "\n"
    "processor\t: 1\n"
    "vendor_id\t: GenuineIntel\n"
    "cpu family\t: 6\n"
    "model\t\t: 106\n"
    "model name\t: another\n";

const char* kAmdGuest =
    "processor\t: 0\n"
    "vendor_id\t: AuthenticAMD\n"
    "cpu family\t: 25\n"
    "model\t\t: 17\n"
    "model name\t: AMD EPYC 9B14\n";

TEST(HostDescription, NamesTheFirstProcessorsModelAndSignature) {
  std::istringstream intel_text(kIntelGuest), amd_text(kAmdGuest);
  const CpuIdentity intel = cpu_identity_of(intel_text), amd = cpu_identity_of(amd_text);
  EXPECT_EQ(intel.model, "Intel(R) Xeon(R) Processor");
  EXPECT_EQ(intel.signature, "GenuineIntel family 6 model 167");
  EXPECT_EQ(amd.signature, "AuthenticAMD family 25 model 17");
}

TEST(HostDescription, SaysUnknownWhereTheFieldsAreMissing) {
  std::istringstream empty(""), partial("processor\t: 0\nvendor_id\t: GenuineIntel\n");
  EXPECT_EQ(cpu_identity_of(empty).model, "unknown");
  EXPECT_EQ(cpu_identity_of(partial).signature, "unknown");
}

TEST(HostDescription, ReadsAnonymousAndHugePageMemory) {
  std::istringstream rollup(
      "55d0c2a4e000-7ffd2e9f6000 ---p 00000000 00:00 0                          [rollup]\n"
      "Rss:             2219800 kB\n"
      "Anonymous:       2210000 kB\n"
      "AnonHugePages:   2203648 kB\n"
      "ShmemPmdMapped:        0 kB\n");
  const MemoryUse use = memory_use_of(rollup);
  EXPECT_DOUBLE_EQ(use.anonymous_bytes, 2210000.0 * 1024);
  EXPECT_DOUBLE_EQ(use.huge_page_bytes, 2203648.0 * 1024);
  std::istringstream none("");
  EXPECT_EQ(memory_use_of(none).huge_page_bytes, 0.0);
}

TEST(HostDescription, ThisProcessHasAnonymousMemory) {
  // Where /proc/self/smaps_rollup exists (Linux 4.14 and later), it lists this process's
  // heap; elsewhere both figures are zero.
  const MemoryUse use = memory_use();
  EXPECT_GE(use.anonymous_bytes, use.huge_page_bytes);
}

}  // namespace
}  // namespace rbcal::bench
