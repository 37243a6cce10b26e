#include "viewer/model/background_priority.h"

#include <sys/resource.h>
#include <tbb/task_scheduler_observer.h>
#include <unistd.h>

namespace meshtrace::viewer {

namespace {
class BackgroundTbbWorkers : public tbb::task_scheduler_observer {
 public:
  BackgroundTbbWorkers() { observe(true); }
  void on_scheduler_entry(bool isWorker) override {
    if (isWorker) runThisThreadInBackground();
  }
};
}  // namespace

// Never stopped, never destroyed: TBB's workers outlive main, and stopping
// the observer while a worker still holds TBB's record of it leaves that
// record unfreed. Reachable from here for the rest of the process.
tbb::task_scheduler_observer* tbbWorkerObserver = nullptr;

void runThisThreadInBackground() {
  // An absolute value: a TBB worker enters the arena many times.
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kBackgroundNice);
}

void runTbbWorkersInBackground() {
  if (!tbbWorkerObserver) tbbWorkerObserver = new BackgroundTbbWorkers;
}

}  // namespace meshtrace::viewer
