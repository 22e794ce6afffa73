#include "bench/host_description.hpp"

#include <unistd.h>

#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "solver/simd.hpp"

namespace rbcal::bench {

namespace {

// "key : value" fields of the first block of /proc/cpuinfo (the first processor).
std::map<std::string, std::string> first_processor(std::istream& in) {
  std::map<std::string, std::string> fields;
  std::string line;
  while (std::getline(in, line)) {
    if (line.find_first_not_of(" \t") == std::string::npos) {
      if (!fields.empty()) break;  // the blank line after the first processor
      continue;
    }
    const auto colon = line.find(':');
    if (colon == std::string::npos) continue;
    std::string key = line.substr(0, colon);
    key.erase(key.find_last_not_of(" \t") + 1);
    const auto value_at = line.find_first_not_of(" \t", colon + 1);
    fields.emplace(key, value_at == std::string::npos ? "" : line.substr(value_at));
  }
  return fields;
}

// The bracketed word of "always [madvise] never".
std::string huge_page_mode() {
  std::ifstream in("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(in, text);
  const auto open = text.find('['), close = text.find(']');
  return open != std::string::npos && close != std::string::npos && close > open ? text.substr(open + 1, close - open - 1)
                                                                                 : "unknown";
}

}  // namespace

CpuIdentity cpu_identity_of(std::istream& cpuinfo) {
  const auto fields = first_processor(cpuinfo);
  CpuIdentity id{"unknown", "unknown"};
  const auto name = fields.find("model name");
  if (name != fields.end() && !name->second.empty()) id.model = name->second;
  const auto vendor = fields.find("vendor_id"), family = fields.find("cpu family"), model = fields.find("model");
  if (vendor != fields.end() && family != fields.end() && model != fields.end())
    id.signature = vendor->second + " family " + family->second + " model " + model->second;
  return id;
}

MemoryUse memory_use_of(std::istream& smaps_rollup) {
  MemoryUse use;
  std::string line;
  while (std::getline(smaps_rollup, line)) {
    std::istringstream fields(line);
    std::string key;
    double kib = 0.0;
    if (!(fields >> key >> kib)) continue;
    if (key == "Anonymous:") use.anonymous_bytes = kib * 1024.0;
    if (key == "AnonHugePages:") use.huge_page_bytes = kib * 1024.0;
  }
  return use;
}

MemoryUse memory_use() {
  std::ifstream in("/proc/self/smaps_rollup");
  return memory_use_of(in);
}

HostDescription describe_host() {
  std::ifstream cpuinfo("/proc/cpuinfo");
  CpuIdentity cpu = cpu_identity_of(cpuinfo);
  return {std::move(cpu.model), std::move(cpu.signature), solver::simd::width, huge_page_mode(),
          sysconf(_SC_PAGESIZE)};
}

std::string HostDescription::line() const {
  return cpu_model + " (" + cpu_signature + "), " + std::to_string(vector_doubles) + " doubles per vector, THP " +
         huge_pages + ", " + std::to_string(page_bytes / 1024) + " KiB pages";
}

}  // namespace rbcal::bench
