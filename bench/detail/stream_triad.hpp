#pragma once
// STREAM-triad memory bandwidth, a[i] = b[i] + s c[i], on all OpenMP threads. Bytes are
// counted as STREAM (McCalpin) counts them, 3 x 8 per element. With ordinary stores
// the hardware also reads each line of a before writing it (write-allocate), traffic
// STREAM does not count; with streaming (non-temporal) stores it does not.
#include <cstddef>

namespace rbcal::bench {

class StreamTriad {
 public:
  explicit StreamTriad(std::size_t elements);
  ~StreamTriad();
  StreamTriad(const StreamTriad&) = delete;
  StreamTriad& operator=(const StreamTriad&) = delete;

  // Seconds for one pass of the triad over the arrays.
  double run_once(bool streaming_stores);
  std::size_t elements() const { return n_; }
  double bytes_counted() const { return 24.0 * static_cast<double>(n_); }

 private:
  std::size_t n_;
  double* a_;
  double* b_;
  double* c_;
};

}  // namespace rbcal::bench
