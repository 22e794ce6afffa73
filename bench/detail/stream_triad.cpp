#include "bench/detail/stream_triad.hpp"

#include "bench/detail/timing.hpp"
#include "solver/aligned_vector.hpp"
#include "solver/simd.hpp"

namespace rbcal::bench {

namespace {
solver::AlignedAllocator<double> allocator;
}

StreamTriad::StreamTriad(std::size_t elements)
    : n_((elements + solver::simd::width - 1) / solver::simd::width * solver::simd::width),
      a_(allocator.allocate(n_)),
      b_(allocator.allocate(n_)),
      c_(allocator.allocate(n_)) {
  const long n = static_cast<long>(n_);
  // First touch by the threads that will stream the data.
#pragma omp parallel for schedule(static)
  for (long i = 0; i < n; ++i) {
    a_[i] = 0.0;
    b_[i] = 1.0;
    c_[i] = 2.0;
  }
}

StreamTriad::~StreamTriad() {
  allocator.deallocate(a_, n_);
  allocator.deallocate(b_, n_);
  allocator.deallocate(c_, n_);
}

double StreamTriad::run_once(bool streaming_stores) {
  using namespace solver::simd;
  const long n = static_cast<long>(n_);
  const double s = 3.0;
  double* a = a_;
  const double* b = b_;
  const double* c = c_;
  if (!streaming_stores) {
    return seconds_of([&] {
#pragma omp parallel for simd schedule(static)
      for (long i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    });
  }
  return seconds_of([&] {
#pragma omp parallel
    {
#pragma omp for schedule(static) nowait
      for (long i = 0; i < n; i += width) store_streaming(a + i, load(b + i) + s * load(c + i));
      store_fence();
    }
  });
}

}  // namespace rbcal::bench
