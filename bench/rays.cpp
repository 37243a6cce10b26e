#include "bench/rays.h"

#include "meshtrace/render/spawn.h"
#include "meshtrace/render/surface.h"

namespace meshtrace::bench {

RaySet primaryRays(const Scene& scene) {
  RaySet set;
  const int w = scene.camera.width(), h = scene.camera.height();
  const auto add = [&](int x, int y) {
    set.rays.push_back(scene.camera.primaryRay(x, y));
    set.tMax.push_back(kInfinity);
  };
  // In Integrator::quad's order.
  for (int y = 0; y + 1 < h; y += 2)
    for (int x = 0; x + 1 < w; x += 2) {
      add(x, y);
      add(x + 1, y);
      add(x, y + 1);
      add(x + 1, y + 1);
      ++set.packets;
    }
  if (w % 2)
    for (int y = 0; y < h - h % 2; ++y) add(w - 1, y);
  if (h % 2)
    for (int x = 0; x < w; ++x) add(x, h - 1);
  return set;
}

RaySet shadowRays(const Scene& scene, const SceneIntersector& intersector, const RaySet& primary) {
  RaySet set;
  if (scene.lights.empty()) return set;
  const Light& light = scene.lights.front();
  Counters c;
  for (const Ray& ray : primary.rays) {
    Hit hit;
    if (!intersector.closestHit(ray, kSpawnTMin, hit, c)) continue;
    const SurfacePoint sp = surfaceAt(scene, ray, hit, intersector.options().triangle.precision);
    const Vec3 l = glm::normalize(light.position - sp.point);
    if (!(glm::dot(sp.normal, l) > 0.0)) continue;
    const Ray shadow{spawnOrigin(sp, l), l};
    set.rays.push_back(shadow);
    set.tMax.push_back(glm::length(light.position - shadow.origin));
    set.start.push_back(sp.primitive);
  }
  return set;
}

}  // namespace meshtrace::bench
