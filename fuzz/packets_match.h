#pragma once
// What the scene and OFF harnesses check of a scene that loads: a spread of
// its 2x2 pixel quads rendered as the renderer does, with packets through
// the BVH, must give each pixel exactly the colour brute force (--accel
// none) gives it alone, as the README promises. A difference aborts, with
// the pixel, so that libFuzzer keeps the input.
#include <cstdio>
#include <cstdlib>

#include "meshtrace/render/integrator.h"

namespace meshtrace::fuzz {

inline void expectPacketsMatchBruteForce(const Scene& scene) {
  const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh});
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  const Integrator packets(bvh), alone(brute);
  Counters counters;
  // Four by four quads, from corner to corner of the image.
  const int w = scene.camera.width(), h = scene.camera.height();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const int x = (w - 1) * i / 3 & ~1, y = (h - 1) * j / 3 & ~1;
      Color quad[kPacketSize];
      packets.quad(x, y, quad, counters);
      for (int k = 0; k < kPacketSize; ++k) {
        const Color c = alone.pixel(x + k % 2, y + k / 2, counters);
        if (c != quad[k] && !(glm::any(glm::isnan(c)) && glm::any(glm::isnan(quad[k])))) {
          std::fprintf(stderr,
                       "pixel (%d, %d): packets through the BVH give %.17g %.17g %.17g, "
                       "brute force %.17g %.17g %.17g\n",
                       x + k % 2, y + k / 2, quad[k].r, quad[k].g, quad[k].b, c.r, c.g, c.b);
          std::abort();
        }
      }
    }
}

}  // namespace meshtrace::fuzz
