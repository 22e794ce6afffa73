#pragma once
// Writes a command's JSON record (pretty-printed) to a file, or throws naming the file.
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

namespace rbcal::cli {

inline void write_json(const std::string& path, const nlohmann::json& j) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("error while writing " + path);
}

}  // namespace rbcal::cli
