#include "bench/host_description.hpp"

#include <unistd.h>

#include <fstream>

#include "solver/simd.hpp"

namespace rbcal::bench {

namespace {

std::string cpu_model() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line))
    if (line.rfind("model name", 0) == 0) {
      const auto colon = line.find(':');
      if (colon != std::string::npos) return line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown";
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

HostDescription describe_host() {
  return {cpu_model(), solver::simd::width, huge_page_mode(), sysconf(_SC_PAGESIZE)};
}

std::string HostDescription::line() const {
  return cpu_model + ", " + std::to_string(vector_doubles) + " doubles per vector, THP " + huge_pages + ", " +
         std::to_string(page_bytes / 1024) + " KiB pages";
}

}  // namespace rbcal::bench
