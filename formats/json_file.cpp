#include "formats/json_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "formats/format_error.hpp"
#include "formats/write_error.hpp"

namespace rbcal::formats {

nlohmann::json read_json_file(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) throw FormatError(file.string(), "is a folder, not a JSON file");
  std::ifstream in(file);
  if (!in) throw FormatError(file.string(), std::string("cannot open: ") + std::strerror(errno));
  std::stringstream text;
  text << in.rdbuf();
  return parse_json_text(text.str(), file.string());
}

nlohmann::json parse_json_text(const std::string& text, const std::string& source) {
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    // e.what() carries "parse error at line L, column C: ..."; e.byte the offset.
    throw FormatError(source, "invalid JSON (byte " + std::to_string(e.byte) + "): " + e.what());
  } catch (const nlohmann::json::exception& e) {
    // Found by fuzzing: a number beyond double's range ("1e999") is out_of_range, not parse_error.
    throw FormatError(source, std::string("invalid JSON: ") + e.what());
  }
}

void write_file_atomically(const std::filesystem::path& file, const std::string& contents) {
  // The process id keeps two writers of one file (two sweep workers) off each other's
  // temporary file.
  const std::filesystem::path temp = file.string() + ".tmp." + std::to_string(::getpid());
  {
    std::ofstream out(temp, std::ios::binary);
    if (!out) throw WriteError(file.string() + ": cannot write (" + temp.string() + "): " + std::strerror(errno));
    out << contents;
    out.flush();
    if (!out) {
      // The reason (a full disk, a folder gone read-only) is the failed write's; the partial
      // temporary file goes.
      const std::string why = std::strerror(errno);
      out.close();
      std::error_code ignored;
      std::filesystem::remove(temp, ignored);
      throw WriteError(file.string() + ": error while writing (" + temp.string() + "): " + why);
    }
  }
  std::error_code ec;
  std::filesystem::rename(temp, file, ec);
  if (ec) {
    const std::string why = ec.message();
    std::filesystem::remove(temp, ec);
    throw WriteError(file.string() + ": cannot replace: " + why);
  }
}

void write_json_atomically(const std::filesystem::path& file, const nlohmann::json& j) {
  write_file_atomically(file, j.dump(2) + "\n");
}

}  // namespace rbcal::formats
