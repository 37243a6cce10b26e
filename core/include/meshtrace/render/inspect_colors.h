#pragma once
// Colour scales for the false-colour views: a heat ramp for counts and
// errors, distinct colours for ids, and the usual normal encoding.
#include <cstdint>

#include "meshtrace/util/math.h"

namespace meshtrace {

// Dark blue (0) through purple, red and orange to pale yellow (1); values
// outside [0, 1] are clamped. Monotonic in brightness, so it reads in grey.
Color heatColor(double t);

// A well-spread, fully saturated colour per id (golden-ratio hues).
Color idColor(std::uint32_t id);

// 0.5 * (n + 1): x to red, y to green, z to blue.
Color normalColor(const Vec3& n);

// Near (1) to far (0.15) in grey, on a scale from `nearT` to `farT`.
Color depthColor(double t, double nearT, double farT);

}  // namespace meshtrace
