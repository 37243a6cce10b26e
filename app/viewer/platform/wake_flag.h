#pragma once
// A flag another thread raises to end a wait: the wake-up of the frame
// loop's pauses when background work hands something over.
#include <chrono>
#include <condition_variable>
#include <mutex>

namespace meshtrace::viewer {

class WakeFlag {
 public:
  using Clock = std::chrono::steady_clock;

  // From any thread: ends the current wait, or the next one.
  void raise() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      raised_ = true;
    }
    woken_.notify_one();
  }

  // Waits until `end` unless the flag is raised (or was, since the last
  // wait); lowers it.
  void waitUntil(Clock::time_point end) {
    std::unique_lock<std::mutex> lock(mutex_);
    woken_.wait_until(lock, end, [&] { return raised_; });
    raised_ = false;
  }
  void waitFor(double ms) {
    waitUntil(Clock::now() + std::chrono::duration_cast<Clock::duration>(
                                 std::chrono::duration<double, std::milli>(ms)));
  }

 private:
  std::mutex mutex_;
  std::condition_variable woken_;
  bool raised_ = false;
};

}  // namespace meshtrace::viewer
