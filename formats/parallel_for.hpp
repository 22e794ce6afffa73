#pragma once
// body(i) for i in [0, count) over OpenMP threads (threads 0: OpenMP's default; parallel false:
// in this thread), each iteration writing only its own results so that they do not depend on
// the number of threads. An exception must not leave an OpenMP region: the first one thrown is
// kept and rethrown once the loop is done.
#include <cstddef>
#include <exception>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace rbcal::formats {

template <class Body>
void parallel_for(std::ptrdiff_t count, int threads, Body&& body, bool parallel = true) {
  std::exception_ptr failure;
#ifdef _OPENMP
  if (threads <= 0) threads = omp_get_max_threads();
#else
  threads = 1;
#endif
#pragma omp parallel for schedule(dynamic) num_threads(threads) if (parallel)
  for (std::ptrdiff_t i = 0; i < count; ++i) {
    try {
      body(i);
    } catch (...) {
#pragma omp critical(rbcal_parallel_for_failure)
      if (!failure) failure = std::current_exception();
    }
  }
  if (failure) std::rethrow_exception(failure);
}

}  // namespace rbcal::formats
