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

inline constexpr std::size_t kCacheLine = 64;

// The lines at p, p + 64, ... below p + bytes: all of them when p starts a
// line.
inline void prefetchLinesFrom(const char* p, std::size_t bytes) {
  for (std::size_t offset = 0; offset < bytes; offset += kCacheLine) prefetchLine(p + offset);
}

// Every cache line of the `bytes` (at least 1) from `data`.
inline void prefetchBytes(const void* data, std::size_t bytes) {
  const char* p = static_cast<const char*>(data);
  prefetchLinesFrom(p, bytes);
  prefetchLine(p + bytes - 1);  // bytes not starting a line may reach into one more
}

// Every cache line of `object`.
template <typename T>
inline void prefetchObject(const T& object) {
  if constexpr (alignof(T) >= kCacheLine)
    prefetchLinesFrom(reinterpret_cast<const char*>(&object), sizeof(T));
  else
    prefetchBytes(&object, sizeof(T));
}

}  // namespace meshtrace
