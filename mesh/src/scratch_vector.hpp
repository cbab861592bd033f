#pragma once

// Working arrays of a polygon's split (one entry or a few per corner), on huge pages where
// they are large. A polygon of a million corners walks a few hundred megabytes of such
// arrays, much of it in sweep order, which is no order in memory: with 4 KiB pages each
// first touch is a page fault and most random reads miss the TLB. Transparent huge pages
// (2 MiB) cut both by 512; Linux gives them to memory that asks (madvise MADV_HUGEPAGE)
// wherever the system setting is `madvise` or `always` (docs/inside.md has the star
// polygon's load before and after). Arrays below 2 MiB, and every array elsewhere than
// Linux, are ordinary allocations.

#include <cstddef>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace exactgeo::mesh::internal {

template <class T>
class HugePageAllocator {
 public:
  using value_type = T;

  HugePageAllocator() noexcept = default;
  template <class U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (!huge(bytes)) return static_cast<T*>(::operator new(bytes, kAlignment));
    void* memory = ::operator new (rounded(bytes), std::align_val_t{kHugePage});
#if defined(__linux__)
    madvise(memory, rounded(bytes), MADV_HUGEPAGE);  // advice: ignored where refused
#endif
    return static_cast<T*>(memory);
  }

  void deallocate(T* memory, std::size_t n) noexcept {
    const std::size_t bytes = n * sizeof(T);
    if (!huge(bytes)) {
      ::operator delete(memory, bytes, kAlignment);
    } else {
      ::operator delete (memory, rounded(bytes), std::align_val_t{kHugePage});
    }
  }

  template <class U>
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator<U>&) noexcept {
    return true;
  }

 private:
  static constexpr std::size_t kHugePage = std::size_t{1} << 21;
  // The element's own alignment (a sweep node asks for a cache line, above what plain
  // operator new promises); a huge allocation's 2 MiB alignment covers it.
  static constexpr std::align_val_t kAlignment{alignof(T)};
  static_assert(alignof(T) <= kHugePage);

  static bool huge(std::size_t bytes) noexcept {
    return bytes >= kHugePage;
  }
  static std::size_t rounded(std::size_t bytes) noexcept {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
  }
};

template <class T>
using ScratchVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace exactgeo::mesh::internal
