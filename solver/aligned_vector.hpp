#pragma once
// std::vector with cache-line aligned storage, so that the lattice's streams
// start on 64-byte boundaries and vector loads/stores never straddle lines. Large
// blocks are 2 MiB aligned and offered to the kernel for transparent huge pages: the
// fluid update walks ~40 streams at once, which thrashes the TLB with 4 KiB pages.
#include <sys/mman.h>

#include <cstddef>
#include <new>
#include <vector>

namespace rbcal::solver {

template <class T, std::size_t Alignment = 64>
struct AlignedAllocator {
  using value_type = T;
  template <class U>
  struct rebind {
    using other = AlignedAllocator<U, Alignment>;
  };
  AlignedAllocator() noexcept = default;
  template <class U>
  AlignedAllocator(const AlignedAllocator<U, Alignment>&) noexcept {}

  static constexpr std::size_t huge_page = std::size_t{2} << 20;

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge_page) return static_cast<T*>(::operator new(bytes, std::align_val_t{Alignment}));
    void* p = ::operator new(bytes, std::align_val_t{huge_page});
    madvise(p, bytes, MADV_HUGEPAGE);  // a hint: failure only costs speed
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t align = n * sizeof(T) < huge_page ? Alignment : huge_page;
    ::operator delete(p, std::align_val_t{align});
  }

  template <class U>
  bool operator==(const AlignedAllocator<U, Alignment>&) const noexcept { return true; }
};

template <class T>
using AlignedVector = std::vector<T, AlignedAllocator<T>>;

}  // namespace rbcal::solver
