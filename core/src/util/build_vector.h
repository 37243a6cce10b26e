#pragma once
// A vector whose resize leaves trivially constructible elements unwritten,
// for large buffers that are filled right after they are sized: the
// build's, filled in parallel, a progressive job's per-pixel buffers
// (render/progressive_job.h) and the preview grid's chunks and cells
// (render/progressive_preview.h). Value-initialising them first would write
// every page from one thread, each first write a page fault, before the
// fill writes them all again: a zero fill costs a large first build about
// a quarter of its blocks' time.
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace meshtrace {

// Buffers of half of kLargePageBytes or more start on a 2 MiB boundary,
// are rounded up to whole 2 MiB pages and are offered to the kernel's
// transparent huge pages (madvise; the kernel may decline, and the memory
// works either way). A large tree is read in random order, and with 4 KiB
// pages the address translations miss too: rays on the large meshes take
// a few percent less time with it (as Embree's buffers are on huge pages).
// From half a page up, so that an image-sized buffer (800 x 600 x 4 bytes)
// is one page fault rather than 469; a buffer of 1-2 MiB takes up to twice
// its size.
inline constexpr std::size_t kLargePageBytes = std::size_t{2} << 20;
void* allocateLarge(std::size_t bytes, std::size_t align);
void freeLarge(void* p, std::size_t bytes, std::size_t align) noexcept;
// Offers the whole 2 MiB pages inside [p, p + bytes) to transparent huge
// pages; nothing for a smaller range.
void offerHugePages(void* p, std::size_t bytes) noexcept;

// Room for `n` elements in a std::vector the public API holds (a mesh's
// arrays), offered to huge pages before anything is written to it: on
// first touch a 2 MiB page costs one page fault instead of 512, which on
// a large mesh's arrays is more of the load than the numbers are.
// Only the whole 2 MiB pages inside are offered, unless the program's
// operator new is ours (large_page_new.cpp), which starts such a vector on
// a 2 MiB boundary: our programs link it, the library leaves it to them.
template <typename T>
void reserveOnLargePages(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  offerHugePages(v.data(), v.capacity() * sizeof(T));
}

template <typename T>
struct UninitializedAllocator : std::allocator<T> {
  template <typename U>
  struct rebind {
    using other = UninitializedAllocator<U>;
  };
  UninitializedAllocator() = default;
  template <typename U>
  UninitializedAllocator(const UninitializedAllocator<U>&) noexcept {}

  // Default-initialisation: nothing is written for a trivial type.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }

  T* allocate(std::size_t n) { return static_cast<T*>(allocateLarge(n * sizeof(T), alignof(T))); }
  void deallocate(T* p, std::size_t n) noexcept { freeLarge(p, n * sizeof(T), alignof(T)); }
};

template <typename T>
using BuildVector = std::vector<T, UninitializedAllocator<T>>;

}  // namespace meshtrace
