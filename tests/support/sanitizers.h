#pragma once
// Whether this build (tests and tools alike) runs under AddressSanitizer
// (scripts/sanitize.sh). Its shadow memory takes terabytes of address
// space, and everything runs several times slower: tests that limit
// address space skip under it, and the heaviest randomised comparisons
// take a share of their rays: enough to take every path of the code under
// the sanitizers, which is what that run is for. The ordinary build, also
// run by CI, takes them all and checks the answers at full count.
#include <cstdint>

namespace meshtrace::test {

inline constexpr bool kBuiltWithAsan =
#ifdef __SANITIZE_ADDRESS__
    true;
#else
    false;
#endif

// Under AddressSanitizer those comparisons take one case in this many.
inline constexpr std::uint64_t kSanitizerDivisor = kBuiltWithAsan ? 16 : 1;

// `count` in the ordinary build, a sixteenth of it under AddressSanitizer.
constexpr std::uint64_t sanitizerShare(std::uint64_t count) {
  return (count + kSanitizerDivisor - 1) / kSanitizerDivisor;
}

}  // namespace meshtrace::test
