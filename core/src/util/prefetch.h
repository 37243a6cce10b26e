#pragma once
// Asking the memory for data ahead of its use, so that the wait for it
// overlaps other work (or other waits) instead of following it.
#include <cstddef>

namespace meshtrace {

// The cache line holding p, into every cache level. An asm statement, not
// _mm_prefetch: GCC 12 deletes _mm_prefetch calls from a loop that does
// nothing else (its dead code elimination takes them for free of effects),
// which silently undid the traversals' prefetching of child nodes.
inline void prefetchLine(const void* p) {
  asm volatile("prefetcht0 %0" : : "m"(*static_cast<const char*>(p)));
}

// Every cache line of `object`.
template <typename T>
inline void prefetchObject(const T& object) {
  constexpr std::size_t kLine = 64;
  const char* p = reinterpret_cast<const char*>(&object);
  for (std::size_t offset = 0; offset < sizeof(T); offset += kLine) prefetchLine(p + offset);
  // An object not aligned to a line may reach into one more.
  if constexpr (alignof(T) < kLine) prefetchLine(p + sizeof(T) - 1);
}

}  // namespace meshtrace
