#include "formats/host_memory.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace rbcal::formats {

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ss(line);
    std::string key;
    std::uint64_t kib = 0;
    if (ss >> key >> kib && key == "MemAvailable:") return kib * 1024;
  }
  return 0;
}

}  // namespace rbcal::formats
