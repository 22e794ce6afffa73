#pragma once
// Comparing two runs of one case bit for bit: their result blocks and their time series.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace rbcal::solver::test_cases {

// A whole file as a string (empty when it cannot be read).
inline std::string slurp(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Two runs of one case, their results and output folders: they agree bit for bit.
inline void expect_same_run(const nlohmann::json& a, const std::filesystem::path& dir_a, const nlohmann::json& b,
                            const std::filesystem::path& dir_b) {
  EXPECT_EQ(a["result"]["eta_re"].get<double>(), b["result"]["eta_re"].get<double>());
  EXPECT_EQ(a["result"]["eta_re_wall"].get<double>(), b["result"]["eta_re_wall"].get<double>());
  EXPECT_EQ(a["result"]["steps"], b["result"]["steps"]);
  EXPECT_EQ(slurp(dir_a / "series.csv"), slurp(dir_b / "series.csv"));
}

}  // namespace rbcal::solver::test_cases
