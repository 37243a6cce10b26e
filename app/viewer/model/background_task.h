#pragma once
// Work the viewer's UI thread must not wait for (loading a scene, building
// its BVH, the OpenMesh check, image comparisons), run on a thread of its
// own. The work reports what it is doing (its phase), hands back results as
// it makes them, and checks between steps whether a newer action cancelled
// it; a cancelled task's results are dropped. Starting a task cancels the
// one before, which ends at its next check while the new one already runs:
// the UI never waits for old work. Tasks run below the UI thread's priority
// (background_priority.h).
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "viewer/model/background_priority.h"

namespace meshtrace::viewer {

// What a task's work sees of its task.
template <typename Result>
class TaskContext {
 public:
  bool cancelled() const { return cancelled_.load(std::memory_order_relaxed); }
  // What the task does now, for the UI ("building the BVH").
  void setPhase(std::string phase) {
    std::lock_guard<std::mutex> lock(mutex_);
    phase_ = std::move(phase);
    phaseStart_ = std::chrono::steady_clock::now();
  }
  // Hands a result to the UI thread (dropped if the task was cancelled).
  void publish(Result result) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (cancelled()) return;
      results_.push_back(std::move(result));
    }
    if (wake_) wake_();
  }

 private:
  template <typename>
  friend class BackgroundTask;

  std::function<void()> wake_;
  std::atomic<bool> cancelled_{false};
  std::atomic<bool> done_{false};
  mutable std::mutex mutex_;
  std::string phase_;
  std::string error_;
  std::chrono::steady_clock::time_point phaseStart_ = std::chrono::steady_clock::now();
  std::vector<Result> results_;
};

template <typename Result>
class BackgroundTask {
 public:
  using Work = std::function<void(TaskContext<Result>&)>;

  // `wake` runs on the task's thread after each result and at its end, so
  // that a UI waiting for input draws a frame.
  explicit BackgroundTask(std::function<void()> wake = {}) : wake_(std::move(wake)) {}
  ~BackgroundTask() {
    cancel();
    for (Running& r : running_) r.thread.join();
  }
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;

  // Cancels the current task and starts `work` on a new thread. An
  // exception that escapes `work` ends it; its message is the task's error.
  void start(Work work, std::string firstPhase) {
    cancel();
    reap();
    auto context = std::make_shared<TaskContext<Result>>();
    context->wake_ = wake_;
    context->phase_ = std::move(firstPhase);
    current_ = context;
    running_.push_back({context, std::thread([context, work = std::move(work)] {
                          runThisThreadInBackground();
                          try {
                            work(*context);
                          } catch (const std::exception& e) {
                            std::lock_guard<std::mutex> lock(context->mutex_);
                            context->error_ = e.what();
                          }
                          context->done_.store(true);
                          if (context->wake_) context->wake_();
                        })});
  }
  // The current task's results stop here; its thread ends at its next check.
  void cancel() {
    if (current_) current_->cancelled_.store(true);
    current_.reset();
  }

  // The current task's results since the last call.
  std::vector<Result> take() {
    std::vector<Result> out;
    if (!current_) return out;
    std::lock_guard<std::mutex> lock(current_->mutex_);
    out.swap(current_->results_);
    return out;
  }
  bool busy() const { return current_ && !current_->done_.load(); }
  // The message of an exception that ended the current task, else empty.
  std::string error() const {
    if (!current_) return {};
    std::lock_guard<std::mutex> lock(current_->mutex_);
    return current_->error_;
  }
  std::string phase() const {
    if (!current_) return {};
    std::lock_guard<std::mutex> lock(current_->mutex_);
    return current_->phase_;
  }
  // How long the current phase has run.
  double phaseMs() const {
    if (!current_) return 0.0;
    std::lock_guard<std::mutex> lock(current_->mutex_);
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() -
                                                     current_->phaseStart_)
        .count();
  }

 private:
  struct Running {
    std::shared_ptr<TaskContext<Result>> context;
    std::thread thread;
  };
  // Joins the threads that have ended (a cancelled one may still run).
  void reap() {
    for (auto it = running_.begin(); it != running_.end();) {
      if (it->context->done_.load()) {
        it->thread.join();
        it = running_.erase(it);
      } else {
        ++it;
      }
    }
  }

  std::function<void()> wake_;
  std::shared_ptr<TaskContext<Result>> current_;
  std::vector<Running> running_;
};

}  // namespace meshtrace::viewer
