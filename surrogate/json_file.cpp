#include "surrogate/json_file.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rbcal::surrogate {

nlohmann::json read_json_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot open");
  std::stringstream text;
  text << in.rdbuf();
  try {
    return nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries "parse error at line L, column C: ..."; e.byte the offset.
    throw std::runtime_error(file.string() + ": invalid JSON (byte " + std::to_string(e.byte) + "): " + e.what());
  }
}

void write_json_file_atomically(const std::filesystem::path& file, const nlohmann::json& j) {
  const std::filesystem::path temp = file.string() + ".tmp";
  {
    std::ofstream out(temp);
    if (!out) throw std::runtime_error(file.string() + ": cannot write");
    out << j.dump(2) << "\n";
    if (!out) throw std::runtime_error(file.string() + ": error while writing");
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) throw std::runtime_error(file.string() + ": cannot replace: " + ec.message());
}

}  // namespace rbcal::surrogate
