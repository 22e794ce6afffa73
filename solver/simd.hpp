#pragma once
// A fixed-width vector of doubles (GCC/Clang vector extension) sized to the widest
// instruction set the build targets, with unaligned loads and non-temporal stores.
// The fluid update is memory bound; streaming stores skip the read-for-ownership of the
// destination lines, which would otherwise add half as much traffic again.
#include <cstddef>
#include <cstring>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace rbcal::solver::simd {

#if defined(__AVX512F__)
inline constexpr int width = 8;
#elif defined(__AVX__)
inline constexpr int width = 4;
#else
inline constexpr int width = 2;
#endif

using vdouble = double __attribute__((vector_size(width * sizeof(double))));
inline constexpr std::size_t bytes = sizeof(vdouble);

inline vdouble load(const double* p) {
  vdouble v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

inline vdouble broadcast(double s) { return vdouble{} + s; }

inline void store(double* p, vdouble v) { std::memcpy(p, &v, sizeof v); }

// p must be aligned to `bytes`. Call store_fence() before other threads read the data.
inline void store_streaming(double* p, vdouble v) {
#if defined(__AVX512F__)
  _mm512_stream_pd(p, reinterpret_cast<__m512d>(v));
#elif defined(__AVX__)
  _mm256_stream_pd(p, reinterpret_cast<__m256d>(v));
#elif defined(__SSE2__)
  _mm_stream_pd(p, reinterpret_cast<__m128d>(v));
#else
  store(p, v);
#endif
}

// One cache line of doubles (8, 64-byte aligned at p and at line) with non-temporal
// stores, its parts back to back: vectors narrower than a line, streamed one per row
// stream, leave many lines half written in the write-combining buffers, and each then
// costs a read and a write (store_line_streaming for floats below).
inline void store_line_streaming(double* p, const double* line) {
#if defined(__AVX512F__)
  _mm512_stream_pd(p, _mm512_load_pd(line));
#elif defined(__AVX__)
  _mm256_stream_pd(p, _mm256_load_pd(line));
  _mm256_stream_pd(p + 4, _mm256_load_pd(line + 4));
#elif defined(__SSE2__)
  for (int i = 0; i < 8; i += 2) _mm_stream_pd(p + i, _mm_load_pd(line + i));
#else
  std::memcpy(p, line, 8 * sizeof(double));
#endif
}

// Floats in the same lanes as vdouble (single-precision storage): loaded widened to double,
// stored narrowed from it.
using vfloat = float __attribute__((vector_size(width * sizeof(float))));

inline vdouble load(const float* p) {
  vfloat v;
  std::memcpy(&v, p, sizeof v);
  return __builtin_convertvector(v, vdouble);
}

inline void store(float* p, vdouble v) {
  const vfloat f = __builtin_convertvector(v, vfloat);
  std::memcpy(p, &f, sizeof f);
}

// One cache line of floats (16, 64-byte aligned at p and at line) with non-temporal
// stores. Lines written whole: partial lines of many streams overflow the write-combining
// buffers, and each half-written line then costs a read and a write.
inline void store_line_streaming(float* p, const float* line) {
#if defined(__AVX512F__)
  _mm512_stream_ps(p, _mm512_load_ps(line));
#elif defined(__AVX__)
  _mm256_stream_ps(p, _mm256_load_ps(line));
  _mm256_stream_ps(p + 8, _mm256_load_ps(line + 8));
#elif defined(__SSE2__)
  for (int i = 0; i < 16; i += 4) _mm_stream_ps(p + i, _mm_load_ps(line + i));
#else
  std::memcpy(p, line, 16 * sizeof(float));
#endif
}

inline void store_fence() {
#if defined(__SSE2__)
  _mm_sfence();
#endif
}

inline bool is_aligned(const double* p) { return reinterpret_cast<std::size_t>(p) % bytes == 0; }

}  // namespace rbcal::solver::simd
