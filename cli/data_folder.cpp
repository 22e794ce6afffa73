#include "cli/data_folder.hpp"

#include <cstdlib>
#include <stdexcept>
#include <system_error>

namespace rbcal::cli {

namespace fs = std::filesystem;

fs::path data_folder() {
  if (const char* env = std::getenv("RBCAL_DATA"); env && *env) {
    if (!fs::is_directory(env)) throw std::runtime_error(std::string("RBCAL_DATA=") + env + ": not a folder");
    return env;
  }
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot locate the rbcal executable (/proc/self/exe): " + ec.message() +
                                   "; set RBCAL_DATA to the data folder");
  const fs::path candidate = (exe.parent_path() / ".." / "share" / "rbcal" / "data").lexically_normal();
  if (!fs::is_directory(candidate))
    throw std::runtime_error("no shipped data at " + candidate.string() +
                             " (next to the executable); set RBCAL_DATA to the data folder");
  // Resolved: in the build tree the link leads to the source tree's data/, and that is
  // the path reports record.
  return fs::canonical(candidate);
}

std::string shipped_file(const std::string& relative) {
  try {
    return (data_folder() / relative).string();
  } catch (const std::runtime_error& e) {
    return std::string("(shipped ") + relative + ": " + e.what() + ")";
  }
}

}  // namespace rbcal::cli
