#pragma once
// printf-style formatting into a std::string of any length (the tables and reports rbcal
// prints are built line by line with it).
#include <cstdio>
#include <string>

namespace rbcal::formats {

template <class... Args>
std::string printf_string(const char* pattern, Args... args) {
  char buffer[512];
  const int n = std::snprintf(buffer, sizeof buffer, pattern, args...);
  if (n < 0) return {};
  if (static_cast<std::size_t>(n) < sizeof buffer) return std::string(buffer, static_cast<std::size_t>(n));
  std::string out(static_cast<std::size_t>(n), '\0');
  std::snprintf(out.data(), out.size() + 1, pattern, args...);
  return out;
}

}  // namespace rbcal::formats
