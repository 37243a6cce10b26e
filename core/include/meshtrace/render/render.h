#pragma once
// Whole-image rendering on all cores. Every pixel is computed independently,
// so the image is the same whatever the thread count.
#include "meshtrace/accel/intersector.h"
#include "meshtrace/io/image.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

struct RenderOptions {
  TraceOptions trace;
  int threads = 0;  // 0: all cores
};

Image render(const Scene& scene, const RenderOptions& options, Counters* counters = nullptr);
// With an intersector built beforehand (so that its build can be timed apart).
Image render(const SceneIntersector& intersector, int threads, Counters* counters = nullptr);
// The same through `camera` instead of the scene's (the viewer's, once moved).
Image render(const SceneIntersector& intersector, const Camera& camera, int threads,
             Counters* counters = nullptr);

// Number of mesh bounding boxes `ray` meets at t >= 0 (a box holding the
// origin counts), as the debug_aabb image counts them.
int boxHitCount(const Scene& scene, const Ray& ray);

// Per pixel, the number of mesh bounding boxes the primary ray meets at t >= 0.
struct BoxHitCounts {
  int width = 0, height = 0;
  std::vector<int> counts;  // row 0 at the top, like Image
  int maxCount = 0;
};
BoxHitCounts countBoxHits(const Scene& scene, int threads = 0);
// Red = count / max count, as the reference debug images.
Image debugAabbImage(const BoxHitCounts& counts);

}  // namespace meshtrace
