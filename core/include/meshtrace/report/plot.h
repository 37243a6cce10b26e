#pragma once
// The plot `raytrace --report` writes for each scene.
#include "meshtrace/io/image.h"
#include "meshtrace/report/report.h"

namespace meshtrace {

// A log-log scatter plot of RMSE (+ 0.01) against seconds, one colour per
// configuration group, with decade ticks labelled by a built-in digit font.
Image plotErrorAgainstTime(const SceneReport& report, int width = 640, int height = 420);

}  // namespace meshtrace
