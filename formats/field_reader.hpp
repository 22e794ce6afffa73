#pragma once
// Field access to a parsed JSON document by dotted path ("training.3.phi": a number
// indexes an array), with errors (FormatError) that name the source and the field:
// "LIB/cases/x.json: field result.eta_re_sem: must be a non-negative number".
// Required fields: number(), positive(), ... fail when the field is missing.
// Optional fields: the *_or() forms return the fallback when the field is absent and
// check closed bounds [lo, hi] when it is present.
#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcal::formats {

class FieldReader {
 public:
  FieldReader(const nlohmann::json& root, std::string source);

  [[noreturn]] void fail(const std::string& field, const std::string& what) const;

  // The node at a dotted path, or nullptr if absent; fails if a parent on the path is
  // neither an object nor an array (a typo there must not look like an absent field).
  const nlohmann::json* find(const std::string& path) const;
  const nlohmann::json& require(const std::string& path) const;
  // Fails on a key of the object at `path` that is not in `known` (a misspelled or retired
  // option must not be ignored silently); an absent object passes.
  void only_known_keys(const std::string& path, const std::vector<std::string>& known) const;

  double number(const std::string& path) const;        // finite
  double positive(const std::string& path) const;      // > 0
  double non_negative(const std::string& path) const;  // >= 0
  double in_range(const std::string& path, double lo, double hi) const;  // lo < v < hi (open)
  long long integer(const std::string& path, long long lo) const;         // >= lo
  std::string text(const std::string& path) const;
  std::vector<double> numbers(const std::string& path, std::size_t min_size) const;

  double number_or(const std::string& path, double fallback, double lo, double hi) const;
  int integer_or(const std::string& path, int fallback, int lo, int hi) const;
  std::string text_or(const std::string& path, const std::string& fallback) const;
  // The document must be a JSON object whose "schema" is `expected`: fails naming what it is
  // (not an object, schema missing, not a string, or another schema).
  void expect_schema(const std::string& expected) const;
  template <std::size_t N>
  std::array<double, N> numbers_or(const std::string& path, const std::array<double, N>& fallback) const {
    const nlohmann::json* n = find(path);
    if (!n) return fallback;
    const std::vector<double> v = fixed_numbers(*n, path, N);
    std::array<double, N> out{};
    for (std::size_t i = 0; i < N; ++i) out[i] = v[i];
    return out;
  }

  const std::string& source() const { return source_; }

 private:
  std::vector<double> fixed_numbers(const nlohmann::json& n, const std::string& path, std::size_t size) const;

  const nlohmann::json& root_;
  std::string source_;
};

}  // namespace rbcal::formats
