#pragma once
// A vector whose resize leaves trivially constructible elements unwritten,
// for the build's large buffers that are filled, in parallel, right after
// they are sized. Value-initialising them first wrote every page from one
// thread, and the first write to a page is a page fault (about 1 us each on
// the benchmark machine), before the fill wrote them all again: the 4.5 MB
// of refined_elephant's triangle blocks took 2.5-2.7 ms in a first build
// that way, 1.9-2.2 ms without the zero fill (1.7 ms once pages are mapped).
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

namespace meshtrace {

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
};

template <typename T>
using BuildVector = std::vector<T, UninitializedAllocator<T>>;

}  // namespace meshtrace
