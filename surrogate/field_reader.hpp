#pragma once
// Required-field access to a parsed JSON document with errors that name the source file
// and the dotted field path: "LIB/cases/x.json: field result.eta_re_sem: must be a
// non-negative number".
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rbcal::surrogate {

class FieldReader {
 public:
  FieldReader(const nlohmann::json& root, std::string source);

  [[noreturn]] void fail(const std::string& field, const std::string& what) const;

  // The node at a dotted path ("training.3.phi": a number indexes an array), or nullptr.
  const nlohmann::json* find(const std::string& path) const;
  const nlohmann::json& require(const std::string& path) const;

  double number(const std::string& path) const;
  double positive(const std::string& path) const;      // > 0
  double non_negative(const std::string& path) const;  // >= 0
  double in_range(const std::string& path, double lo, double hi) const;  // lo < v < hi (open)
  long long integer(const std::string& path, long long lo) const;         // >= lo
  std::string text(const std::string& path) const;
  std::vector<double> numbers(const std::string& path, std::size_t min_size) const;

  const std::string& source() const { return source_; }

 private:
  const nlohmann::json& root_;
  std::string source_;
};

}  // namespace rbcal::surrogate
