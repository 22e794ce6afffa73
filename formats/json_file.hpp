#pragma once
// Reading and writing the project's JSON files (cases, plans, libraries, surrogates,
// reports). Reading errors name the file, and for syntax errors the byte, line and
// column; writing goes through a temporary file and a rename, so a reader (or a run
// killed mid-write) never leaves half a file behind.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

namespace rbcal::formats {

// Throws FormatError "FILE: cannot open" or "FILE: invalid JSON (byte B): ... line L,
// column C ...".
nlohmann::json read_json_file(const std::filesystem::path& file);
// The same for text already in memory; source names it in errors.
nlohmann::json parse_json_text(const std::string& text, const std::string& source);

// Writes the bytes of contents to file via FILE.tmp.PID and a rename (atomic on one file
// system); throws std::runtime_error naming the file.
void write_file_atomically(const std::filesystem::path& file, const std::string& contents);

// Pretty-printed JSON (two-space indent, final newline), written atomically.
void write_json_atomically(const std::filesystem::path& file, const nlohmann::json& j);

}  // namespace rbcal::formats
