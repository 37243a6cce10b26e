// The flag that ends the frame loop's pause when background work hands
// something over.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "viewer/platform/wake_flag.h"

namespace meshtrace::viewer {
namespace {

using Clock = WakeFlag::Clock;

double msSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

TEST(WakeFlag, WaitsUntilTheEndWhenNotRaised) {
  WakeFlag flag;
  const Clock::time_point start = Clock::now();
  flag.waitFor(30.0);
  EXPECT_GE(msSince(start), 30.0);
}

TEST(WakeFlag, ARaiseFromAnotherThreadEndsTheWaitEarly) {
  WakeFlag flag;
  const Clock::time_point start = Clock::now();
  std::thread raiser([&] {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    flag.raise();
  });
  flag.waitFor(10'000.0);
  raiser.join();
  const double waited = msSince(start);
  EXPECT_GE(waited, 20.0);
  EXPECT_LT(waited, 5'000.0) << "the raise did not end the wait";
}

// A hand-over that comes while the loop draws a frame must not wait for
// the pause after it; the pause after that is a whole pause again.
TEST(WakeFlag, ARaiseBeforeTheWaitEndsItAtOnceAndOnlyIt) {
  WakeFlag flag;
  flag.raise();
  Clock::time_point start = Clock::now();
  flag.waitFor(10'000.0);
  EXPECT_LT(msSince(start), 5'000.0) << "the earlier raise was lost";
  start = Clock::now();
  flag.waitFor(30.0);
  EXPECT_GE(msSince(start), 30.0) << "one raise ended two waits";
}

}  // namespace
}  // namespace meshtrace::viewer
