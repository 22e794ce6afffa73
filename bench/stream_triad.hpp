#pragma once
// STREAM-triad memory bandwidth, a[i] = b[i] + s c[i], on all OpenMP threads. Bytes
// counted as in STREAM (McCalpin): 3 x 8 per element, write-allocate traffic not
// counted, so that it compares like for like with the lattice-update byte count.
#include <cstddef>
#include <vector>

namespace rbcal::bench {

struct TriadResult {
  std::size_t elements = 0;
  int threads = 0;
  std::vector<double> seconds;    // one per repetition
  double median_bytes_per_s = 0;  // 24 * elements / median(seconds)
};

TriadResult measure_stream_triad(std::size_t elements, int repetitions);

}  // namespace rbcal::bench
