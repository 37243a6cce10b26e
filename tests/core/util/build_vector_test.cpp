#include "util/build_vector.h"

#include <gtest/gtest.h>

#include <cstdint>

namespace meshtrace {
namespace {

bool startsOnHugePage(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % kLargePageBytes == 0;
}

TEST(BuildVector, LargeBuffersStartOnAHugePageBoundary) {
  BuildVector<std::uint32_t> large(kLargePageBytes / sizeof(std::uint32_t) + 1);
  EXPECT_TRUE(startsOnHugePage(large.data()));
}

// An 800 x 600 RGBA image (a progressive job's colours) is under 2 MiB
// and still gets a huge page of its own: one page fault, not 469.
TEST(BuildVector, ImageSizedBuffersStartOnAHugePageBoundary) {
  BuildVector<std::uint8_t> rgba(800 * 600 * 4);
  EXPECT_TRUE(startsOnHugePage(rgba.data()));
}

TEST(BuildVector, KeepsItsContentsWhenGrowingPastTheLargeSize) {
  BuildVector<std::uint64_t> values;
  const std::size_t n = 3 * kLargePageBytes / sizeof(std::uint64_t);
  for (std::size_t i = 0; i < n; ++i) values.push_back(i * 2654435761u);
  EXPECT_TRUE(startsOnHugePage(values.data()));
  for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(values[i], i * 2654435761u) << i;
  values.clear();
  values.shrink_to_fit();  // small again: the ordinary allocation path
  values.push_back(7);
  EXPECT_EQ(values[0], 7u);
}

TEST(BuildVector, OverAlignedElementsKeepTheirAlignmentInSmallBuffers) {
  struct alignas(64) Line {
    std::uint8_t bytes[64];
  };
  BuildVector<Line> lines(3);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(lines.data()) % 64, 0u);
}

}  // namespace
}  // namespace meshtrace
