#include "meshtrace/integrator.h"

#include "whitted.h"

namespace meshtrace {

Color Integrator::trace(const Ray& ray, int level, Counters& counters) const {
  NoObserver none;
  return whittedTrace(intersector_, ray, level, counters, none);
}

Color Integrator::pixel(const Camera& camera, double x, double y, Counters& counters) const {
  ++counters.primaryRays;
  return trace(camera.primaryRay(x, y), 0, counters);
}

void Integrator::quad(double x, double y, Color out[4], Counters& counters) const {
  const Scene& scene = intersector_.scene();
  const Camera& camera = scene.camera;
  const Ray rays[kPacketSize] = {camera.primaryRay(x, y), camera.primaryRay(x + 1, y),
                                 camera.primaryRay(x, y + 1), camera.primaryRay(x + 1, y + 1)};
  Hit hits[kPacketSize];
  bool found[kPacketSize];
  intersector_.closestHitPacket(rays, kSpawnTMin, hits, found, counters);
  counters.primaryRays += kPacketSize;
  NoObserver none;
  if (scene.lights.size() > kMaxPacketLights) {
    for (int r = 0; r < kPacketSize; ++r)
      out[r] = whittedShade(intersector_, rays[r], found[r], hits[r], 0, counters, none);
    return;
  }
  SurfacePoint sp[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r)
    if (found[r])
      sp[r] = surfaceAt(scene, rays[r], hits[r], intersector_.options().triangle.precision);
  // Each light's shadow rays from the four hits go as one packet; rays not
  // cast (no hit, light behind) keep the primary ray as a placeholder.
  std::uint32_t blocked[kMaxPacketLights];
  for (std::size_t i = 0; i < scene.lights.size(); ++i) {
    Ray shadow[kPacketSize] = {rays[0], rays[1], rays[2], rays[3]};
    double lightDistance[kPacketSize] = {0.0, 0.0, 0.0, 0.0};
    PrimitiveRef start[kPacketSize];
    std::uint32_t cast = 0;
    for (int r = 0; r < kPacketSize; ++r) {
      Vec3 l;
      double nl;
      if (found[r] && shadowRayToward(scene.lights[i], sp[r], l, nl, shadow[r], lightDistance[r])) {
        start[r] = sp[r].primitive;
        cast |= 1u << r;
      }
    }
    blocked[i] =
        intersector_.occludedPacket(shadow, kSpawnTMin, lightDistance, start, cast, counters);
  }
  for (int r = 0; r < kPacketSize; ++r) {
    if (!found[r]) {
      out[r] = scene.background;
      continue;
    }
    const auto shadowed = [&](std::size_t i, const Ray&, double) {
      return (blocked[i] >> r & 1) != 0;
    };
    out[r] = whittedShadeAt(intersector_, rays[r], hits[r], sp[r], 0, counters, none, shadowed);
  }
}

Color Integrator::pixel(double x, double y, Counters& counters) const {
  return pixel(intersector_.scene().camera, x, y, counters);
}

}  // namespace meshtrace
