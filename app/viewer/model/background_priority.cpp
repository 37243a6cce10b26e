#include "viewer/model/background_priority.h"

#include <sys/resource.h>
#include <unistd.h>

namespace meshtrace::viewer {

void runThisThreadInBackground() {
  // An absolute value: a TBB worker enters the arena many times.
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kBackgroundNice);
}

}  // namespace meshtrace::viewer
