// The worker behind the disposer and the settings writer: tasks in the
// order posted, on a thread other than the poster's, none lost at the end.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <thread>
#include <vector>

#include "viewer/model/disposer.h"
#include "viewer/model/serial_worker.h"

namespace meshtrace::viewer {
namespace {

TEST(SerialWorker, RunsTasksInTheOrderPostedOffThePostersThread) {
  std::vector<int> order;
  std::atomic<bool> onPoster = false;
  const std::thread::id poster = std::this_thread::get_id();
  SerialWorker worker;
  for (int i = 0; i < 100; ++i)
    worker.post([&, i] {
      if (std::this_thread::get_id() == poster) onPoster = true;
      order.push_back(i);
    });
  worker.flush();
  ASSERT_EQ(order.size(), 100u);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(order[i], i);
  EXPECT_FALSE(onPoster);
}

TEST(SerialWorker, WhatIsQueuedWhenItGoesStillRuns) {
  std::atomic<int> ran = 0;
  {
    SerialWorker worker;
    worker.post([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      ++ran;
    });
    for (int i = 0; i < 10; ++i) worker.post([&] { ++ran; });
  }
  EXPECT_EQ(ran, 11);
}

// The last reference to a disposed object goes on the worker's thread,
// not on the thread that let go of it.
TEST(Disposer, TheLastReferenceGoesOnItsOwnThread) {
  struct Noted {
    std::thread::id* freedOn;
    ~Noted() { *freedOn = std::this_thread::get_id(); }
  };
  std::thread::id freedOn;
  {
    Disposer disposer;
    disposer.dispose(std::make_shared<Noted>(&freedOn));
  }
  EXPECT_NE(freedOn, std::thread::id());
  EXPECT_NE(freedOn, std::this_thread::get_id());
}

}  // namespace
}  // namespace meshtrace::viewer
