#pragma once
// Checks of numeric options that name the problem in words: CLI11's PositiveNumber printed
// its upper bound, the largest double, as a 309-digit number, and a NaN or infinity is no
// option value at all.
#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace rbcal::cli {

namespace detail {

inline CLI::Validator number_check(const char* name, bool zero_allowed) {
  return CLI::Validator(
      [zero_allowed](std::string& text) -> std::string {
        double x = 0.0;
        try {
          std::size_t used = 0;
          x = std::stod(text, &used);
          if (used != text.size()) return "'" + text + "' is not a number";
        } catch (const std::exception&) {
          return "'" + text + "' is not a number";
        }
        if (!std::isfinite(x)) return "must be a finite number, not " + text;
        if (zero_allowed ? x < 0.0 : x <= 0.0)
          return std::string("must be ") + (zero_allowed ? "zero or positive" : "positive") + ", not " + text;
        return "";
      },
      name);
}

}  // namespace detail

// A finite number above 0.
inline const CLI::Validator kPositive = detail::number_check("POSITIVE", false);
// A finite number at or above 0.
inline const CLI::Validator kNonNegative = detail::number_check("NON-NEGATIVE", true);
// Any finite number.
inline const CLI::Validator kFinite = CLI::Validator(
    [](std::string& text) -> std::string {
      try {
        std::size_t used = 0;
        const double x = std::stod(text, &used);
        if (used != text.size()) return "'" + text + "' is not a number";
        return std::isfinite(x) ? "" : "must be a finite number, not " + text;
      } catch (const std::exception&) {
        return "'" + text + "' is not a number";
      }
    },
    "FINITE");

}  // namespace rbcal::cli
