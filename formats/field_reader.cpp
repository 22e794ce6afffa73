#include "formats/field_reader.hpp"

#include <cmath>
#include <sstream>

#include "formats/format_error.hpp"
#include "formats/short_number.hpp"

namespace rbcal::formats {

namespace {

bool is_index(const std::string& key) {
  return !key.empty() && key.size() < 10 && key.find_first_not_of("0123456789") == std::string::npos;
}

}  // namespace

FieldReader::FieldReader(const nlohmann::json& root, std::string source) : root_(root), source_(std::move(source)) {}

void FieldReader::fail(const std::string& field, const std::string& what) const {
  throw FormatError(source_, field, what);
}

void FieldReader::only_known_keys(const std::string& path, const std::vector<std::string>& known) const {
  const nlohmann::json* node = find(path);
  if (!node || !node->is_object()) return;
  for (const auto& [key, value] : node->items()) {
    bool ok = false;
    for (const std::string& k : known) ok = ok || k == key;
    if (ok) continue;
    std::string list;
    for (const std::string& k : known) list += (list.empty() ? "" : ", ") + k;
    fail(path.empty() ? key : path + "." + key, "unknown field (known here: " + list + ")");
  }
}

const nlohmann::json* FieldReader::find(const std::string& path) const {
  const nlohmann::json* node = &root_;
  std::stringstream ss(path);
  std::string key;
  while (std::getline(ss, key, '.')) {
    if (node->is_array()) {
      if (!is_index(key)) fail(path, "parent is an array, not an object");
      const std::size_t index = std::stoul(key);
      if (index >= node->size()) return nullptr;
      node = &(*node)[index];
      continue;
    }
    if (!node->is_object()) fail(path, "parent is not an object");
    auto it = node->find(key);
    if (it == node->end()) return nullptr;
    node = &*it;
  }
  return node;
}

const nlohmann::json& FieldReader::require(const std::string& path) const {
  const nlohmann::json* n = find(path);
  if (!n) fail(path, "missing");
  return *n;
}

double FieldReader::number(const std::string& path) const {
  const nlohmann::json& n = require(path);
  if (!n.is_number()) fail(path, "must be a number");
  const double v = n.get<double>();
  if (!std::isfinite(v)) fail(path, "must be a finite number");
  return v;
}

double FieldReader::positive(const std::string& path) const {
  const nlohmann::json& n = require(path);
  if (!n.is_number() || !(n.get<double>() > 0.0) || !std::isfinite(n.get<double>()))
    fail(path, "must be a positive number");
  return n.get<double>();
}

double FieldReader::non_negative(const std::string& path) const {
  const nlohmann::json& n = require(path);
  if (!n.is_number() || !(n.get<double>() >= 0.0) || !std::isfinite(n.get<double>()))
    fail(path, "must be a non-negative number");
  return n.get<double>();
}

double FieldReader::in_range(const std::string& path, double lo, double hi) const {
  const double v = number(path);
  if (!(v > lo && v < hi)) fail(path, "must be in (" + short_number(lo) + ", " + short_number(hi) + "), got " + short_number(v));
  return v;
}

long long FieldReader::integer(const std::string& path, long long lo) const {
  const nlohmann::json& n = require(path);
  if (!n.is_number_integer()) fail(path, "must be an integer");
  const long long v = n.get<long long>();
  if (v < lo) fail(path, "must be an integer >= " + std::to_string(lo));
  return v;
}

std::string FieldReader::text(const std::string& path) const {
  const nlohmann::json& n = require(path);
  if (!n.is_string()) fail(path, "must be a string");
  return n.get<std::string>();
}

std::vector<double> FieldReader::numbers(const std::string& path, std::size_t min_size) const {
  const nlohmann::json& n = require(path);
  const std::string what = "must be an array of at least " + std::to_string(min_size) + " finite numbers";
  if (!n.is_array() || n.size() < min_size) fail(path, what);
  std::vector<double> out;
  for (const auto& e : n) {
    if (!e.is_number() || !std::isfinite(e.get<double>())) fail(path, what);
    out.push_back(e.get<double>());
  }
  return out;
}

double FieldReader::number_or(const std::string& path, double fallback, double lo, double hi) const {
  const nlohmann::json* n = find(path);
  if (!n) return fallback;
  if (!n->is_number()) fail(path, "must be a number");
  const double v = n->get<double>();
  if (!(v >= lo && v <= hi)) fail(path, "must be in [" + short_number(lo) + ", " + short_number(hi) + "], got " + short_number(v));
  return v;
}

int FieldReader::integer_or(const std::string& path, int fallback, int lo, int hi) const {
  const nlohmann::json* n = find(path);
  if (!n) return fallback;
  if (!n->is_number_integer()) fail(path, "must be an integer");
  const long long v = n->get<long long>();
  if (v < lo || v > hi) fail(path, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<int>(v);
}

std::string FieldReader::text_or(const std::string& path, const std::string& fallback) const {
  const nlohmann::json* n = find(path);
  if (!n) return fallback;
  if (!n->is_string()) fail(path, "must be a string");
  return n->get<std::string>();
}

void FieldReader::expect_schema(const std::string& expected) const {
  if (!root_.is_object()) fail("(top level)", "must be a JSON object");
  const std::string schema = text("schema");
  if (schema != expected) fail("schema", "must be \"" + expected + "\", got \"" + schema + "\"");
}

std::vector<double> FieldReader::fixed_numbers(const nlohmann::json& n, const std::string& path,
                                               std::size_t size) const {
  const std::string what = "must be an array of " + std::to_string(size) + " numbers";
  if (!n.is_array() || n.size() != size) fail(path, what);
  std::vector<double> out;
  for (const auto& e : n) {
    if (!e.is_number() || !std::isfinite(e.get<double>())) fail(path, what);
    out.push_back(e.get<double>());
  }
  return out;
}

}  // namespace rbcal::formats
