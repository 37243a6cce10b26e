#include "util/build_vector.h"

#include <sys/mman.h>

#include <cstdint>

namespace meshtrace {

namespace {

bool isLarge(std::size_t bytes) { return bytes >= kLargePageBytes / 2; }

}  // namespace

void* allocateLarge(std::size_t bytes, std::size_t align) {
  if (!isLarge(bytes)) return ::operator new (bytes, std::align_val_t{align});
  // Round up so the last huge page is whole, and advise before the first
  // write: pages are chosen when first touched.
  const std::size_t rounded = (bytes + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
  void* p = ::operator new (rounded, std::align_val_t{kLargePageBytes});
  madvise(p, rounded, MADV_HUGEPAGE);
  return p;
}

void offerHugePages(void* p, std::size_t bytes) noexcept {
  const auto begin = reinterpret_cast<std::uintptr_t>(p);
  const std::uintptr_t first = (begin + kLargePageBytes - 1) / kLargePageBytes * kLargePageBytes;
  const std::uintptr_t last = (begin + bytes) / kLargePageBytes * kLargePageBytes;
  if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
}

void freeLarge(void* p, std::size_t bytes, std::size_t align) noexcept {
  if (!isLarge(bytes)) {
    ::operator delete (p, std::align_val_t{align});
    return;
  }
  ::operator delete (p, std::align_val_t{kLargePageBytes});
}

}  // namespace meshtrace
