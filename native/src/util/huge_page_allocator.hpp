// Footfall — an allocator that backs large blocks with transparent huge pages.
// The planners' per-thread scratch (search nodes, sampled agents) grows to
// tens of megabytes, per thread; each 4 KiB page it touches first costs a
// page fault, and under a hypervisor a fault costs microseconds.
// Blocks of 2 MiB and more are mapped on their own, aligned to 2 MiB and
// marked for huge pages (Linux's "madvise" THP mode), so one fault maps 2 MiB.
// Smaller blocks, and systems without madvise, come from the heap.
#pragma once

#include <cstddef>
#include <cstdint>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace footfall {

namespace huge_pages {

#if defined(__linux__) && defined(MADV_HUGEPAGE)
constexpr bool kMapped = true;
#else
constexpr bool kMapped = false;  // elsewhere everything comes from the heap
#endif
constexpr std::size_t kSize = std::size_t{2} << 20;  ///< x86-64's huge page. [bytes]

inline std::size_t rounded(std::size_t bytes) { return (bytes + kSize - 1) / kSize * kSize; }

/// `bytes` (a multiple of kSize) of fresh memory aligned to kSize.
inline void* map(std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Over-map by one huge page, then cut the ends off to align.
  void* raw = mmap(nullptr, bytes + kSize, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                   -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const auto begin = reinterpret_cast<std::uintptr_t>(raw);
  const std::uintptr_t aligned = (begin + kSize - 1) / kSize * kSize;
  const std::uintptr_t end = begin + bytes + kSize;
  if (aligned > begin) munmap(raw, aligned - begin);
  if (end > aligned + bytes) munmap(reinterpret_cast<void*>(aligned + bytes), end - aligned - bytes);
  void* block = reinterpret_cast<void*>(aligned);
  madvise(block, bytes, MADV_HUGEPAGE);  // a hint: without huge pages the block still works
  return block;
#else
  (void)bytes;
  throw std::bad_alloc();
#endif
}

inline void unmap(void* block, std::size_t bytes) {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  munmap(block, bytes);
#else
  (void)block;
  (void)bytes;
#endif
}

}  // namespace huge_pages

/// std::allocator, except that blocks of 2 MiB and more are mapped with huge pages.
template <class T>
struct HugePageAllocator {
  static_assert(alignof(T) <= __STDCPP_DEFAULT_NEW_ALIGNMENT__, "over-aligned types need more");
  using value_type = T;

  HugePageAllocator() = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    const std::size_t bytes = n * sizeof(T);
    if (large(bytes)) return static_cast<T*>(huge_pages::map(huge_pages::rounded(bytes)));
    return static_cast<T*>(::operator new(bytes));
  }

  void deallocate(T* p, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (large(bytes)) {
      huge_pages::unmap(p, huge_pages::rounded(bytes));
    } else {
      ::operator delete(p);
    }
  }

  friend bool operator==(const HugePageAllocator&, const HugePageAllocator&) { return true; }
  friend bool operator!=(const HugePageAllocator&, const HugePageAllocator&) { return false; }

 private:
  static bool large(std::size_t bytes) { return huge_pages::kMapped && bytes >= huge_pages::kSize; }
};

/// A vector that may grow to megabytes: per-thread scratch kept between searches.
template <class T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace footfall
