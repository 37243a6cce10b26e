#include "viewer/model/render_progress.h"

#include <algorithm>

namespace meshtrace::viewer {

std::optional<double> aaTimeLeftMs(const ProgressiveStatus& s) {
  if (s.finished || !s.exactDone || s.exactMs < 0) return std::nullopt;
  int aaDone = 0;
  double last = s.exactMs;
  for (const double ms : s.passMs) {
    if (ms > s.exactMs) ++aaDone;
    last = std::max(last, ms);
  }
  if (aaDone == 0) return std::nullopt;
  const int remaining = std::max(0, s.passCount - s.passesDone);
  return remaining * (last - s.exactMs) / aaDone;
}

}  // namespace meshtrace::viewer
