#include "solver/io/json_file.hpp"

#include <fstream>
#include <stdexcept>

namespace rbcal::solver {

nlohmann::json read_json_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot open " + what + " " + path);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::parse_error& e) {
    throw std::invalid_argument(path + ": not valid JSON (byte " + std::to_string(e.byte) + "): " + e.what());
  }
}

}  // namespace rbcal::solver
