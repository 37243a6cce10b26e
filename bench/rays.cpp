#include "rays.h"

#include "meshtrace/spawn.h"
#include "meshtrace/surface.h"

namespace meshtrace::bench {

RaySet primaryRays(const Scene& scene) {
  RaySet set;
  const int w = scene.camera.width(), h = scene.camera.height();
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      set.rays.push_back(scene.camera.primaryRay(x, y));
      set.tMax.push_back(kInfinity);
    }
  return set;
}

RaySet shadowRays(const Scene& scene, const SceneIntersector& intersector,
                  const RaySet& primary) {
  RaySet set;
  if (scene.lights.empty()) return set;
  const Light& light = scene.lights.front();
  Counters c;
  for (const Ray& ray : primary.rays) {
    Hit hit;
    if (!intersector.closestHit(ray, kSpawnTMin, hit, c)) continue;
    const SurfacePoint sp =
        surfaceAt(scene, ray, hit, intersector.options().triangle.precision);
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
