#pragma once
// Reads a JSON file; errors name the file (and the byte where parsing failed).
#include <nlohmann/json.hpp>
#include <string>

namespace rbcal::solver {

// what: how the file is named in the error if it cannot be opened ("case file").
nlohmann::json read_json_file(const std::string& path, const std::string& what);

}  // namespace rbcal::solver
