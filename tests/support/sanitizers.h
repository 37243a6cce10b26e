#pragma once
// Whether this build (tests and tools alike) runs under AddressSanitizer
// (scripts/sanitize.sh). Its shadow memory takes terabytes of address
// space, and everything runs several times slower: tests that limit
// address space skip under it, and the heaviest randomised comparisons
// take a share of their rays (the ordinary build, also run by CI, takes
// them all).
#include <cstdint>

namespace meshtrace::test {

inline constexpr bool kBuiltWithAsan =
#ifdef __SANITIZE_ADDRESS__
    true;
#else
    false;
#endif

// `count` in the ordinary build, a quarter of it under AddressSanitizer.
constexpr std::uint64_t sanitizerShare(std::uint64_t count) {
  return kBuiltWithAsan ? (count + 3) / 4 : count;
}

}  // namespace meshtrace::test
