#pragma once
// How far the anti-aliasing passes after the exact image have come, for
// the render panel: the time left, from the passes done so far.
#include <optional>

#include "meshtrace/render/progressive.h"

namespace meshtrace::viewer {

// The time the remaining passes will take at the average pace of the
// anti-aliasing passes completed since the exact image; none before the
// exact image and its first such pass, and none once finished. A pause
// counts in the pace.
std::optional<double> aaTimeLeftMs(const ProgressiveStatus& status);

}  // namespace meshtrace::viewer
