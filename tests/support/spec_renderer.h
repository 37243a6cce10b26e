#pragma once
// A second renderer, written from the scene format's page (camera, Cramer's
// rule, Whitted shading, 8-bit truncation) and nothing else of ours: it
// shares no code with core's accel and render rooms, only the Scene the
// parser loaded. It is plain and slow where the library is careful and
// fast: a median-split BVH of its own, spawned rays pushed a fixed
// distance off the surface, ties between equal distances to whichever
// primitive comes first. Where both follow the page, their images agree
// but for pixels where a rounding decision goes the other way (silhouettes,
// shared edges, shadow boundaries grazing a surface).
#include "meshtrace/geometry/scene.h"
#include "meshtrace/io/image.h"

namespace meshtrace::test {

// The scene rendered as the page describes, 8-bit, top row first.
Image8 renderBySpec(const Scene& scene);

}  // namespace meshtrace::test
