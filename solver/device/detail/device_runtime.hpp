#pragma once
// Where the device path (device_stepper.hpp) runs and keeps its memory: on an NVIDIA GPU
// when the file is compiled by nvcc (a build with -DRBCAL_CUDA=ON), otherwise on the
// host's OpenMP threads with ordinary memory. The device code is written once, as loops
// over an index (for_each) whose bodies are host-and-device lambdas, with atomic updates
// where threads meet; the host build of the same code is what CI tests.
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "solver/device/host_device.hpp"

#if defined(__CUDACC__)
#include <cuda_runtime.h>
// A loop body that runs on the device (and, compiled for the host, there too).
#define RBCAL_KERNEL_LAMBDA [=] __host__ __device__
#else
#define RBCAL_KERNEL_LAMBDA [=]
#endif

namespace rbcal::solver::device {

// True in the nvcc build: the loops run on the GPU.
#if defined(__CUDACC__)
inline constexpr bool kOnGpu = true;

inline void check(cudaError_t e, const char* what) {
  if (e != cudaSuccess) throw std::runtime_error(std::string("CUDA: ") + what + ": " + cudaGetErrorString(e));
}

template <class F>
__global__ void for_each_kernel(std::size_t n, F f) {
  const std::size_t i = static_cast<std::size_t>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}
#else
inline constexpr bool kOnGpu = false;
#endif

// Runs f(i) for i in [0, n), in parallel, in no particular order.
template <class F>
void for_each(std::size_t n, F f) {
  if (n == 0) return;
#if defined(__CUDACC__)
  constexpr unsigned threads = 256;
  for_each_kernel<<<static_cast<unsigned>((n + threads - 1) / threads), threads>>>(n, f);
  check(cudaGetLastError(), "kernel launch");
#else
  // Below some thousands of iterations a thread team costs more than it saves (and, on a
  // loaded host, its spin-waits cost far more).
  const long count = static_cast<long>(n);
#pragma omp parallel for schedule(static) if (count >= 16384)
  for (long i = 0; i < count; ++i) f(static_cast<std::size_t>(i));
#endif
}

// Waits for every loop started so far (a no-op on the host).
inline void synchronize() {
#if defined(__CUDACC__)
  check(cudaDeviceSynchronize(), "synchronize");
#endif
}

RBCAL_HD inline void atomic_add(double* p, double v) {
#if defined(__CUDA_ARCH__)
  atomicAdd(p, v);
#else
  std::atomic_ref<double>(*p).fetch_add(v, std::memory_order_relaxed);
#endif
}

// *p = max(*p, v) for v >= 0 (non-negative doubles order as their bit patterns).
RBCAL_HD inline void atomic_max_nonnegative(double* p, double v) {
#if defined(__CUDA_ARCH__)
  atomicMax(reinterpret_cast<unsigned long long*>(p), static_cast<unsigned long long>(__double_as_longlong(v)));
#else
  std::atomic_ref<double> a(*p);
  double current = a.load(std::memory_order_relaxed);
  while (v > current && !a.compare_exchange_weak(current, v, std::memory_order_relaxed)) {
  }
#endif
}

// An array of T in the device's memory (zero-filled on resize).
template <class T>
class Buffer {
 public:
  Buffer() = default;
  explicit Buffer(std::size_t n) { resize(n); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() { release(); }

  void resize(std::size_t n) {
    release();
    size_ = n;
    if (n == 0) return;
#if defined(__CUDACC__)
    check(cudaMalloc(reinterpret_cast<void**>(&data_), n * sizeof(T)), "allocating device memory");
#else
    host_.assign(n, T{});
    data_ = host_.data();
#endif
    fill_zero();
  }
  void fill_zero() {
#if defined(__CUDACC__)
    if (size_) check(cudaMemset(data_, 0, size_ * sizeof(T)), "clearing device memory");
#else
    std::fill(host_.begin(), host_.end(), T{});
#endif
  }
  // Copies n elements between host memory and [offset, offset + n) of the buffer.
  void upload(const T* from, std::size_t n, std::size_t offset = 0) {
    require_range(n, offset);
#if defined(__CUDACC__)
    check(cudaMemcpy(data_ + offset, from, n * sizeof(T), cudaMemcpyHostToDevice), "copy to the device");
#else
    std::copy(from, from + n, data_ + offset);
#endif
  }
  void download(T* to, std::size_t n, std::size_t offset = 0) const {
    require_range(n, offset);
#if defined(__CUDACC__)
    check(cudaMemcpy(to, data_ + offset, n * sizeof(T), cudaMemcpyDeviceToHost), "copy from the device");
#else
    std::copy(data_ + offset, data_ + offset + n, to);
#endif
  }
  // Exchanges the contents with another buffer (the two population arrays).
  void swap(Buffer& other) {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
#if !defined(__CUDACC__)
    host_.swap(other.host_);
#endif
  }
  // Copies all of another buffer of the same size, device to device.
  void copy_from(const Buffer& other) {
    if (other.size_ != size_) throw std::invalid_argument("device buffer: copy between sizes");
#if defined(__CUDACC__)
    if (size_) check(cudaMemcpy(data_, other.data_, size_ * sizeof(T), cudaMemcpyDeviceToDevice), "device copy");
#else
    std::copy(other.host_.begin(), other.host_.end(), host_.begin());
#endif
  }
  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  void require_range(std::size_t n, std::size_t offset) const {
    if (offset + n > size_) throw std::out_of_range("device buffer: copy past its end");
  }
  void release() {
#if defined(__CUDACC__)
    if (data_) cudaFree(data_);
#endif
    data_ = nullptr;
    size_ = 0;
  }
  T* data_ = nullptr;
  std::size_t size_ = 0;
#if !defined(__CUDACC__)
  std::vector<T> host_;
#endif
};

}  // namespace rbcal::solver::device
