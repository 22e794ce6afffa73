#include "surrogate/field_reader.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace rbcal::surrogate {

FieldReader::FieldReader(const nlohmann::json& root, std::string source) : root_(root), source_(std::move(source)) {}

void FieldReader::fail(const std::string& field, const std::string& what) const {
  throw std::invalid_argument(source_ + ": field " + field + ": " + what);
}

const nlohmann::json* FieldReader::find(const std::string& path) const {
  const nlohmann::json* node = &root_;
  std::stringstream ss(path);
  std::string key;
  while (std::getline(ss, key, '.')) {
    if (node->is_array() && !key.empty() && key.find_first_not_of("0123456789") == std::string::npos) {
      const std::size_t index = std::stoul(key);
      if (index >= node->size()) return nullptr;
      node = &(*node)[index];
      continue;
    }
    if (!node->is_object()) return nullptr;
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
  if (!(v > lo && v < hi)) {
    std::ostringstream s;
    s << "must be in (" << lo << ", " << hi << "), got " << v;
    fail(path, s.str());
  }
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

}  // namespace rbcal::surrogate
