#pragma once
// A vector whose resize leaves trivially constructible elements unwritten,
// for the build's large buffers that are filled, in parallel, right after
// they are sized. Value-initialising them first would write every page from
// one thread, each first write a page fault, before the fill writes them all
// again: a zero fill costs a large first build about a quarter of its
// blocks' time.
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace meshtrace {

// Buffers of kLargePageBytes or more start on a 2 MiB boundary and are
// offered to the kernel's transparent huge pages (madvise; the kernel may
// decline, and the memory works either way). A large tree is read in random
// order, and with 4 KiB pages the address translations miss too: rays on
// the large meshes take a few percent less time with it (as Embree's
// buffers are on huge pages).
inline constexpr std::size_t kLargePageBytes = std::size_t{2} << 20;
void* allocateLarge(std::size_t bytes, std::size_t align);
void freeLarge(void* p, std::size_t bytes, std::size_t align) noexcept;

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
