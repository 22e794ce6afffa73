#include "formats/provenance.hpp"

#include <unistd.h>

#include <cstdlib>
#include <ctime>

#include "rbcal/build_info.hpp"

namespace rbcal::formats {

std::string host_name() {
  char name[256] = {0};
  return gethostname(name, sizeof(name) - 1) == 0 ? std::string(name) : std::string("unknown");
}

std::string utc_date() {
  std::time_t t = std::time(nullptr);
  if (const char* epoch = std::getenv("SOURCE_DATE_EPOCH")) {
    char* end = nullptr;
    const long long v = std::strtoll(epoch, &end, 10);
    if (end != epoch && *end == '\0' && v >= 0) t = static_cast<std::time_t>(v);
  }
  std::tm utc{};
  gmtime_r(&t, &utc);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", &utc);
  return buf;
}

nlohmann::json provenance_block() {
  return {{"rbcal_version", build_info::version},
          {"git_revision", build_info::git_revision},
          {"date", utc_date()},
          {"host", host_name()},
          {"build_target", build_info::build_target}};
}

}  // namespace rbcal::formats
