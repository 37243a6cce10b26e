#include "viewer/model/disposer.h"

#include "viewer/model/background_priority.h"

namespace meshtrace::viewer {

Disposer::~Disposer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_one();
  if (thread_.joinable()) thread_.join();
}

void Disposer::dispose(std::shared_ptr<const void> object) {
  if (!object) return;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.push_back(std::move(object));
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  }
  wake_.notify_one();
}

void Disposer::run() {
  runThisThreadInBackground();
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    wake_.wait(lock, [&] { return stopping_ || !pending_.empty(); });
    std::vector<std::shared_ptr<const void>> objects;
    objects.swap(pending_);
    lock.unlock();
    objects.clear();
    lock.lock();
    if (stopping_ && pending_.empty()) return;
  }
}

}  // namespace meshtrace::viewer
