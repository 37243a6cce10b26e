#pragma once
// Lets go of large objects (a scene of millions of triangles, its BVH or
// grid) on a thread of its own: freeing hundreds of megabytes hands the
// pages back to the system, which can take longer than a frame has.
#include <memory>
#include <utility>

#include "viewer/model/serial_worker.h"

namespace meshtrace::viewer {

class Disposer {
 public:
  // Takes `object` (a null one is ignored); its last reference, if this
  // is it, goes on the disposer's thread.
  void dispose(std::shared_ptr<const void> object) {
    if (object) worker_.post([held = std::move(object)]() mutable { held.reset(); });
  }

 private:
  SerialWorker worker_;
};

}  // namespace meshtrace::viewer
