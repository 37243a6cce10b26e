#include "meshtrace/integrator.h"

#include "meshtrace/spawn.h"

namespace meshtrace {

Color Integrator::localColor(const Vec3& viewDir, const SurfacePoint& sp,
                             Counters& counters) const {
  const Scene& scene = intersector_.scene();
  const Material& m = *sp.material;
  Color color = scene.ambience * m.ambient;
  for (const Light& light : scene.lights) {
    const Vec3 toLight = light.position - sp.point;
    const Vec3 l = glm::normalize(toLight);
    const double nl = glm::dot(sp.normal, l);
    // A light behind the surface adds nothing, so its shadow ray is left out.
    if (!(nl > 0.0)) continue;
    const Ray shadow{spawnOrigin(sp, l), l};
    ++counters.shadowRays;
    // The blocker test runs to the light's distance from the shadow ray's own
    // origin: a blocker near the light counts as much as one near the point.
    const double lightDistance = glm::length(light.position - shadow.origin);
    if (intersector_.occluded(shadow, kSpawnTMin, lightDistance, counters)) continue;
    color += light.color * m.diffuse * nl;
    const Vec3 r = 2.0 * nl * sp.normal - l;
    const double rv = glm::dot(r, viewDir);
    if (rv > 0.0) color += light.color * m.specular * std::pow(rv, m.shininess);
  }
  return color;
}

Color Integrator::trace(const Ray& ray, int level, Counters& counters) const {
  const Scene& scene = intersector_.scene();
  Hit hit;
  if (!intersector_.closestHit(ray, kSpawnTMin, hit, counters)) return scene.background;
  const SurfacePoint sp = surfaceAt(scene, ray, hit, intersector_.options().triangle.precision);
  const Color local = localColor(-ray.direction, sp, counters);
  const double mirror = sp.material->mirror;
  // The deepest level keeps its local colour rather than mixing with black.
  if (mirror <= 0.0 || level >= scene.depth) return local;
  const Vec3 d = ray.direction;
  const Vec3 reflected = d - 2.0 * glm::dot(d, sp.normal) * sp.normal;
  const Ray bounce{spawnOrigin(sp, reflected), glm::normalize(reflected)};
  ++counters.reflectionRays;
  return (1.0 - mirror) * local + mirror * trace(bounce, level + 1, counters);
}

Color Integrator::pixel(double x, double y, Counters& counters) const {
  ++counters.primaryRays;
  return trace(intersector_.scene().camera.primaryRay(x, y), 0, counters);
}

}  // namespace meshtrace
