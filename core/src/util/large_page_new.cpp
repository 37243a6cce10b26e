// The global operator new of a program that links meshtrace::large_page_new
// (our programs do; the library itself replaces nothing): an allocation of
// half of kLargePageBytes or more goes where BuildVector's buffers go
// (allocateLarge: 2 MiB-aligned, rounded up to whole huge pages and offered
// to the kernel's transparent huge pages), every other one to malloc.
//
// Why: the arrays a large mesh's load fills (MeshData's and Mesh's
// vectors, the text pieces) are std::vectors the public API holds, and
// malloc places them 16 bytes past a 4 KiB page. Offering the whole 2 MiB
// pages inside them (reserveOnLargePages) leaves up to 2 MiB at each end in
// 4 KiB pages, each first write a page fault: most of a load's faults.
//
// Everything is freed with free(): allocateLarge's memory comes from the
// aligned operator new, which is aligned_alloc in libstdc++, so one
// operator delete serves both.
#include <cstdlib>
#include <new>

#include "util/build_vector.h"

namespace {
void* allocate(std::size_t bytes) {
  using meshtrace::kLargePageBytes;
  if (bytes >= kLargePageBytes / 2)
    return meshtrace::allocateLarge(bytes, __STDCPP_DEFAULT_NEW_ALIGNMENT__);
  if (bytes == 0) bytes = 1;
  for (;;) {
    if (void* p = std::malloc(bytes)) return p;
    const std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}
}  // namespace

// The array, nothrow and sized forms of libstdc++ call these two, so they
// need no replacement of their own.
void* operator new(std::size_t bytes) { return allocate(bytes); }
void operator delete(void* p) noexcept { std::free(p); }
