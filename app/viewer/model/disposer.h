#pragma once
// Lets go of large objects (a scene of millions of triangles, its BVH or
// grid) on a thread of its own: freeing hundreds of megabytes hands the
// pages back to the system, which can take longer than a frame has.
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace meshtrace::viewer {

class Disposer {
 public:
  Disposer() = default;
  ~Disposer();
  Disposer(const Disposer&) = delete;
  Disposer& operator=(const Disposer&) = delete;

  // Takes `object` (a null one is ignored); its last reference, if this
  // is it, goes on the disposer's thread.
  void dispose(std::shared_ptr<const void> object);

 private:
  void run();

  std::mutex mutex_;
  std::condition_variable wake_;
  std::vector<std::shared_ptr<const void>> pending_;
  bool stopping_ = false;
  std::thread thread_;  // started with the first object
};

}  // namespace meshtrace::viewer
