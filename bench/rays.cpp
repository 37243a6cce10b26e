#include "bench/rays.h"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <random>

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

RaySet bounceRays(const Scene& scene, const SceneIntersector& intersector, const RaySet& primary,
                  Bounce bounce) {
  RaySet set;
  std::mt19937_64 random(20261125);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Counters c;
  for (const Ray& ray : primary.rays) {
    Hit hit;
    if (!intersector.closestHit(ray, kSpawnTMin, hit, c)) continue;
    const SurfacePoint sp = surfaceAt(scene, ray, hit, intersector.options().triangle.precision);
    Vec3 d;
    if (bounce == Bounce::Mirror) {
      d = glm::reflect(ray.direction, sp.normal);
    } else {
      // Uniform on the sphere (z uniform in [-1, 1], an angle around z),
      // turned into the normal's hemisphere.
      const double z = 2.0 * unit(random) - 1.0, phi = 2.0 * glm::pi<double>() * unit(random);
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      d = Vec3(r * std::cos(phi), r * std::sin(phi), z);
      if (glm::dot(d, sp.normal) < 0.0) d = -d;
    }
    set.rays.push_back({spawnOrigin(sp, d), d});
    set.tMax.push_back(kInfinity);
    set.start.push_back(sp.primitive);
  }
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
