#include "bench/stream_triad.hpp"

#include <omp.h>

#include <memory>

#include "bench/timing.hpp"
#include "solver/aligned_vector.hpp"

namespace rbcal::bench {

TriadResult measure_stream_triad(std::size_t elements, int repetitions) {
  // Raw aligned buffers, first touched by the threads that will use them.
  solver::AlignedAllocator<double> alloc;
  double* a = alloc.allocate(elements);
  double* b = alloc.allocate(elements);
  double* c = alloc.allocate(elements);
  const long n = static_cast<long>(elements);
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    a[i] = 0.0;
    b[i] = 1.0;
    c[i] = 2.0;
  }
  const double s = 3.0;
  auto triad = [&] {
#pragma omp parallel for simd schedule(static)
    for (long i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
  };
  triad();  // warm-up

  TriadResult result;
  result.elements = elements;
  result.threads = omp_get_max_threads();
  for (int r = 0; r < repetitions; ++r) result.seconds.push_back(seconds_of(triad));
  result.median_bytes_per_s = 24.0 * static_cast<double>(elements) / median(result.seconds);
  alloc.deallocate(a, elements);
  alloc.deallocate(b, elements);
  alloc.deallocate(c, elements);
  return result;
}

}  // namespace rbcal::bench
