// The memory plan: sizes as users write them, reservations refused beyond
// the limit (from several threads at once too), and the default limit
// under an address-space limit.
#include "meshtrace/io/memory_budget.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <stdexcept>

#include "support/files.h"
#include "support/run_tool.h"

namespace meshtrace {
namespace {

TEST(ParseByteSize, ReadsUnitsInPowersOf1024) {
  EXPECT_EQ(parseByteSize("123456"), 123456u);
  EXPECT_EQ(parseByteSize("64k"), 64u << 10);
  EXPECT_EQ(parseByteSize("512M"), 512u << 20);
  EXPECT_EQ(parseByteSize("800MiB"), 800u << 20);
  EXPECT_EQ(parseByteSize("2G"), std::uint64_t{2} << 30);
  EXPECT_EQ(parseByteSize("1.5GB"), std::uint64_t{3} << 29);
  EXPECT_EQ(parseByteSize("1T"), std::uint64_t{1} << 40);
  EXPECT_EQ(parseByteSize("100B"), 100u);
}

TEST(ParseByteSize, RefusesWhatIsNoSize) {
  for (const char* bad : {"", "lots", "-1G", "2X", "G", "1e30", "nan", "12 M"})
    EXPECT_THROW(parseByteSize(bad), std::invalid_argument) << bad;
}

TEST(FormatBytes, SaysMegabytesOrGigabytes) {
  EXPECT_EQ(formatBytes(std::uint64_t{5} << 19), "2.5 MB");
  EXPECT_EQ(formatBytes(std::uint64_t{864} << 20), "864 MB");
  EXPECT_EQ(formatBytes(std::uint64_t{3} << 29), "1.5 GB");
}

TEST(MemoryBudget, RefusesWhatWouldPassTheLimitNamingPhaseAndSizes) {
  MemoryBudget budget(std::uint64_t{100} << 20);
  budget.reserve(std::uint64_t{60} << 20, "load", "the mesh");
  try {
    budget.reserve(std::uint64_t{50} << 20, "build", "the BVH of 7 triangles");
    FAIL() << "110 MB were planned under a limit of 100 MB";
  } catch (const MemoryLimitError& e) {
    test::expectMentions(e.what(), {"cannot build the BVH of 7 triangles", "50 MB more",
                                    "110 MB in all", "limit of 100 MB"});
  }
  EXPECT_EQ(budget.planned(), std::uint64_t{60} << 20) << "a refusal plans nothing";
  budget.release(std::uint64_t{20} << 20);
  budget.reserve(std::uint64_t{50} << 20, "build", "the BVH");
  EXPECT_EQ(budget.planned(), std::uint64_t{90} << 20);
  EXPECT_THROW(budget.reserve(~std::uint64_t{0}, "load", "everything"), MemoryLimitError)
      << "no wrap-around";
}

TEST(MemoryBudget, ReservesFromManyThreadsWithoutPassingTheLimit) {
  MemoryBudget budget(1000);
  std::atomic<int> granted = 0, refused = 0;
  tbb::parallel_for(0, 5000, [&](int) {
    try {
      budget.reserve(1, "load", "a byte");
      ++granted;
    } catch (const MemoryLimitError&) {
      ++refused;
    }
  });
  EXPECT_EQ(granted.load(), 1000);
  EXPECT_EQ(refused.load(), 4000);
  EXPECT_EQ(budget.planned(), 1000u);
}

TEST(WithinMemory, TurnsRunningOutIntoAMessageNamingThePhase) {
  try {
    withinMemory("render", "the image of 9x9 pixels", 2048,
                 []() -> int { throw std::bad_alloc(); });
    FAIL() << "nothing thrown";
  } catch (const MemoryLimitError& e) {
    test::expectMentions(e.what(), {"not enough memory to render the image of 9x9 pixels"});
  }
  EXPECT_EQ(withinMemory("load", "x", 1, [] { return 7; }), 7);
}

// The address space limit (soft, so the test can raise it again) caps the
// default at three quarters of what is left of it.
TEST(DefaultMemoryLimit, IsAShareOfPhysicalMemoryAndOfTheAddressSpaceLeft) {
  EXPECT_LE(defaultMemoryLimit(), physicalMemoryBytes());
  EXPECT_GE(defaultMemoryLimit(), physicalMemoryBytes() / 2);
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
  rlimit saved{};
  ASSERT_EQ(getrlimit(RLIMIT_AS, &saved), 0);
  rlimit limited = saved;
  limited.rlim_cur = rlim_t{4} << 30;
  ASSERT_EQ(setrlimit(RLIMIT_AS, &limited), 0);
  const std::uint64_t underLimit = defaultMemoryLimit();
  setrlimit(RLIMIT_AS, &saved);
  EXPECT_LT(underLimit, std::uint64_t{3} << 30);
  EXPECT_GT(underLimit, std::uint64_t{1} << 30) << "the test process uses far less than 2.7 GB";
}

}  // namespace
}  // namespace meshtrace
