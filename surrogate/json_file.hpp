#pragma once
// Reading a JSON file with errors that name the file (and, for syntax errors, the line
// and column nlohmann reports), shared by the case, plan and surrogate readers.
#include <filesystem>
#include <nlohmann/json.hpp>

namespace rbcal::surrogate {

nlohmann::json read_json_file(const std::filesystem::path& file);

// Writes pretty-printed JSON through a temporary file and a rename, so a reader never sees
// half a file; throws naming the file.
void write_json_file_atomically(const std::filesystem::path& file, const nlohmann::json& j);

}  // namespace rbcal::surrogate
