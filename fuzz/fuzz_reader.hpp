#pragma once
// The harness of every fuzz target: feed the bytes to a reader; a clear rejection is a
// std::exception whose message names the source ("fuzz-input"), anything else is a bug
// and aborts (libFuzzer then saves the input): an exception without the source in its
// message, an exception of another type, or what AddressSanitizer / UBSan report.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <string>

namespace rbcal::fuzz {

inline constexpr const char* kSource = "fuzz-input";

template <class Reader>
int run_reader(const std::uint8_t* data, std::size_t size, Reader&& read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    read(text);
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "out of memory on an input of %zu bytes\n", size);
    std::abort();
  } catch (const std::exception& e) {
    if (std::string(e.what()).find(kSource) == std::string::npos) {
      std::fprintf(stderr, "rejection that does not name the input: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}

}  // namespace rbcal::fuzz
