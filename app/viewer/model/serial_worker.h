#pragma once
// Runs tasks one after another, in the order they were posted, on a thread
// of its own (started with the first task) below the UI thread's
// priority: work a frame must not wait for, such as letting go of a large
// scene or writing the settings file (flush() waits for it where a caller
// must). What is still queued when the worker is destroyed runs before it
// goes.
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>

namespace meshtrace::viewer {

class SerialWorker {
 public:
  SerialWorker() = default;
  ~SerialWorker();
  SerialWorker(const SerialWorker&) = delete;
  SerialWorker& operator=(const SerialWorker&) = delete;

  void post(std::function<void()> task);
  // Waits until every task posted so far has run.
  void flush();

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::function<void()>> tasks_;
  bool running_ = false;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace meshtrace::viewer
